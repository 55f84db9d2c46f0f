// HDRP's real passes of GregoryTerrain.shader (the tessellated SubShader's DepthForwardOnly and
// ForwardOnly), compiled against HDRP 14.0.12's includes and drawn by the harness on lavapipe with every
// binding filled by name from URP's scene in HDRP's units (Tools~/rig/pipeline_pass_hdrp.py): a sun of
// 100,000 lux through a fixed exposure of 15 EV100 (the samples' SampleSun), a sky ambient probe of 0.2
// times the sun's lux / pi, the cascade data over an atlas at the far plane. One run draws five pictures
// (URP's ForwardLit, HDRP's normal buffer, HDRP's lit colour, and that 50 km from the origin and at the
// origin with the same float32 rounding); the tests grade HDRP's against URP's, against Lambert of its
// own normal buffer, and its camera-relative precision. They fail (never skip) when a tool or lavapipe is missing.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class PipelinePassHdrpGpuTests
    {
        /// <summary>The scene's arguments (pipeline_pass_hdrp.py's defaults, written out so a reader sees them).</summary>
        static readonly string[] Scene = { "--sun-elevation", "30", "--sun-azimuth", "-140", "--light-color", "1,0.96,0.9" };
        // pipeline_pass_hdrp.py's SUN_LUX, SUN_EV100 and SKY_SHARE: the samples' HDRP sun and exposure, the sky's share.
        const double Lux = 100000, Ev100 = 15, SkyShare = 0.2;

        const double Quantum = 2.0 / 255.0;

        string _out;
        RigPng _urp, _normalBuffer, _hdrp;
        double[] _albedo, _sun, _light;
        double _scale;              // HDRP's picture over URP's where the models agree: lux / pi x exposure
        List<int> _covered;

        [OneTimeSetUp]
        public void Draw()
        {
            (_out, _) = PipelinePassRun.Draw("pipeline_pass_hdrp.py", "rigtests-pipeline-pass-hdrp", Scene);
            _urp = RigPng.Read(Path.Combine(_out, "lit.png"));
            _normalBuffer = RigPng.Read(Path.Combine(_out, "hdrp_depth.png"));
            _hdrp = RigPng.Read(Path.Combine(_out, "hdrp_lit.png"));
            JsonElement urp = Manifest("lit");
            _sun = urp.GetProperty("sun").EnumerateArray().Select(e => e.GetDouble()).ToArray();
            _light = urp.GetProperty("light_color").EnumerateArray().Select(e => e.GetDouble()).ToArray();
            _albedo = PipelinePassRun.Shading().Albedo;
            // HDRP's fixed exposure (PhysicalCamera.hlsl ConvertEV100ToExposure, scale 1.2) times the
            // sun's lux through Lambert's 1/pi: 0.8095 for the samples' sun.
            _scale = Lux / Math.PI / (1.2 * Math.Pow(2, Ev100));
            // Covered: what URP's ForwardLit drew (a grey terrain colour is never the sky's). The normal buffer
            // cannot say it: an encoded normal may be the sky's colour (measured: one pixel, (140, 178, 229)).
            _covered = PipelinePassRun.Covered(_urp);
            Assert.That(_covered.Count, Is.GreaterThan(_hdrp.Width * _hdrp.Height / 5), "the terrain covers a fifth of the picture or more");
        }


        JsonElement Manifest(string picture) => PipelinePassRun.Manifest(_out, picture);

        static string[] Strings(JsonElement e) => PipelinePassRun.Strings(e);

        double Channel(RigPng png, int p, int c) => png.Rgba[4 * p + c] / 255.0;

        /// <summary>The world normal HDRP's normal buffer holds at the pixel (EncodeIntoNormalBuffer: Packing.hlsl's
        /// PackNormalOctQuadEncode and PackFloat2To888, two 12-bit octahedral coordinates in RGB 8:8:8), decoded.</summary>
        double[] NormalBufferNormal(int p) => PipelinePassRun.OctahedralNormal(_normalBuffer, p);

        double NDotL(int p) => NormalBufferNormal(p).Select((n, c) => n * _sun[c]).Sum();

        double Luminance(RigPng png, int p) => (Channel(png, p, 0) + Channel(png, p, 1) + Channel(png, p, 2)) / 3;

        [Test]
        public void EveryMemberAndBufferMemberTheStagesRead_IsFilledByTheScene_AndEveryDefaultIsListed()
        {
            foreach (string picture in new[] { "hdrp_depth", "hdrp_lit" })
            {
                JsonElement m = Manifest(picture);
                string[] defaults = Strings(m.GetProperty("defaults")), filled = Strings(m.GetProperty("filled"));
                string[] read = m.GetProperty("reads").EnumerateObject().SelectMany(s => Strings(s.Value)).Distinct().ToArray();
                TestContext.Out.WriteLine($"{picture}: {filled.Length} filled, {defaults.Length} defaulted, {read.Length} read");
                Assert.That(Strings(m.GetProperty("defaulted_read")), Is.Empty, picture + ": a member some stage reads was left to its default");
                Assert.That(read.Where(r => !filled.Contains(r)), Is.Empty, picture + ": read but not filled by the scene");
            }
            JsonElement lit = Manifest("hdrp_lit");
            string[] frag = Strings(lit.GetProperty("reads").GetProperty("frag"));
            Assert.That(frag, Does.Contain("_DirectionalLightDatas[0].forward").And.Contain("_DirectionalLightDatas[0].color")
                .And.Contain("ShaderVariablesGlobal._DirectionalShadowIndex").And.Contain("ShaderVariablesGlobal._ProbeExposureScale"),
                "ForwardOnly's fragment stage reads HDRP's directional light and exposure");
            // The exposure texture is the scene's (multiplier, EV100), not pipeline_pass.py's default of 1.
            string exposure = Strings(lit.GetProperty("filled")).SingleOrDefault(f => f.StartsWith("_ExposureTexture="));
            Assert.That(exposure, Does.StartWith("_ExposureTexture=R32G32_SFLOAT(2.54313e-05,15)"), "the exposure texture's texel");
        }

        [Test]
        public void NoPixelIsNaNOrInf_AndEveryCoveredPixelIsWithinLambertsBounds_AfterHdrpsExposure()
        {
            // scale x albedo x (sky .. sky + light), one 8-bit step either side.
            double[] lo = Enumerable.Range(0, 3).Select(c => _scale * _albedo[c] * SkyShare - Quantum).ToArray();
            double[] hi = Enumerable.Range(0, 3).Select(c => _scale * _albedo[c] * (SkyShare + _light[c]) + Quantum).ToArray();
            TestContext.Out.WriteLine($"scale {_scale:F4}");
            PipelinePassRun.AssertWithinBounds(_hdrp, _covered, lo, hi, PipelinePassRun.IsSky, "scale x albedo x (sky .. sky + light)");
        }

        [Test]
        public void SunlitAndTurnedAwaySlopes_AreInTheirBrightnessRanges_AfterHdrpsExposure()
        {
            // Issue 37's fear: a constant 0.2 ambient times the 2.5e-5 exposure (black where the sun does not
            // reach). Expected: 0.81 x 0.55 x (0.2 + 0.95 N.L): about 0.40-0.50 at N.L > 0.7, 0.09-0.22 below 0.3.
            var lit = _covered.Where(p => NDotL(p) > 0.7).Select(p => Luminance(_hdrp, p)).ToList();
            var away = _covered.Where(p => NDotL(p) < 0.3).Select(p => Luminance(_hdrp, p)).ToList();
            TestContext.Out.WriteLine($"N.L > 0.7: {lit.Count} pixels, mean {(lit.Count > 0 ? lit.Average() : double.NaN):F3}, " +
                                      $"min {(lit.Count > 0 ? lit.Min() : double.NaN):F3}; N.L < 0.3: {away.Count} pixels, " +
                                      $"mean {(away.Count > 0 ? away.Average() : double.NaN):F3}, min {(away.Count > 0 ? away.Min() : double.NaN):F3}");
            Assert.That(lit.Count, Is.GreaterThan(_covered.Count / 50), "slopes facing the sun (N.L > 0.7) cover 2% of the terrain or more");
            Assert.That(away.Count, Is.GreaterThan(_covered.Count / 50), "slopes turned away (N.L < 0.3) cover 2% of the terrain or more");
            Assert.That(lit.Average(), Is.InRange(0.30, 0.60), "mean brightness of the sunlit slopes");
            Assert.That(away.Average(), Is.InRange(0.06, 0.30), "mean brightness of the turned-away slopes");
            Assert.That(away.Min(), Is.GreaterThan(0.05), "darkest turned-away pixel (the sky probe keeps it from black)");
        }

        [Test]
        public void TheLitPicture_IsLambertOfItsOwnNormalBuffer_WithTheScenesSun()
        {
            // Per pixel: scale x albedo x (sky + light x saturate(N.L)), N decoded from DepthForwardOnly's
            // normal buffer (12-bit octahedral: N.L within ~0.002), colour 8-bit: 3/255 bounds one pixel.
            PipelinePassRun.AssertWithinEightBitSteps(
                PipelinePassRun.LambertErrors(_hdrp, _covered, NDotL, _scale, _albedo, SkyShare, _light), "|HDRP - Lambert(normal buffer)|");
        }

        [Test]
        public void TheNormalBuffer_HoldsCoresNormals_AtThePixelsDepth()
        {
            // As PipelinePassDepthNormalsTests grades URP's octahedral target (the same packing): DepthForwardOnly's
            // normal buffer decoded the HDRP way (NormalBuffer.hlsl:38-44 DecodeFromNormalBuffer: Unpack888ToFloat2, * 2 - 1,
            // UnpackNormalOctQuadEncode) against Core's normal at the position its depth gives, every 2nd pixel.
            var (angles, outside, worst) = PipelinePassRun.NormalAngles(_out, "hdrp_depth_depth.f32", "hdrp_depth_view.json", _normalBuffer,
                                                                 NormalBufferNormal, 2);
            var (mean, p99, max) = PipelinePassRun.AngleFigures(angles, "HDRP normal buffer vs Core");
            TestContext.Out.WriteLine($"sampled pixels off the terrain: {outside}; {worst}");
            Assert.That(outside, Is.LessThan(angles.Count / 100), "sampled pixels whose depth puts them off the terrain");
            Assert.That(mean, Is.LessThan(PipelinePassDepthNormalsTests.MeanDegrees), "mean angle (degrees)");
            Assert.That(p99, Is.LessThan(PipelinePassDepthNormalsTests.P99Degrees), "99th percentile angle (degrees)");
            Assert.That(max, Is.LessThan(PipelinePassDepthNormalsTests.MaxDegrees), "largest angle (degrees)");
        }

        [Test]
        public void ForwardOnlyOverThePrepassDepth_ShadesEveryPixelTheDepthPassCovered_AndNoOther()
        {
            // HDRP's frame: DepthForwardOnly writes the depth, ForwardOnly draws over that same target with the state
            // ShaderLab gives it (ZTest LEqual, ZWrite On: reversed, GREATER_OR_EQUAL). Both passes tessellate alike
            // (the same stages, _ScreenSize and matrices), so every pixel the prepass covered is shaded (a forward depth
            // one float32 step farther would fail the test: a hole), none outside it, and the depth ForwardOnly leaves
            // is the prepass's to the bit (one step nearer would pass and write it). Holes nil and depth unchanged is
            // exactly what ZTest Equal (HDRP's own opaque forward materials) needs to draw the same pixels.
            JsonElement state = Manifest("hdrp_lit").GetProperty("state");
            Assert.That(string.Join(" ", Strings(state)), Does.Contain("--ztest lequal").And.Contain("--zwrite on"), "ForwardOnly's ShaderLab state");
            string log = File.ReadAllText(Path.Combine(_out, "hdrp_lit", "harness.log"));
            Assert.That(log, Does.Contain("--depth-in"), "ForwardOnly loads the prepass's depth target");
            var (holes, outside, changed, covered) = FrameCoverage(_out, _hdrp);
            TestContext.Out.WriteLine($"prepass covered {covered}; holes {holes}; shaded outside the prepass {outside}; depth changed by ForwardOnly {changed}");
            Assert.That(covered, Is.GreaterThan(_hdrp.Width * _hdrp.Height / 5), "pixels the prepass covered");
            Assert.That(holes, Is.Zero, "pixels the prepass covered that ForwardOnly left unshaded (holes)");
            Assert.That(outside, Is.Zero, "pixels ForwardOnly shaded that the prepass did not cover");
            Assert.That(changed, Is.Zero, "pixels whose depth ForwardOnly changed (its depth is not the prepass's)");
        }

        [Test]
        public void TheFramesStencil_HoldsHdrpsIsUnlitBit_UnderTheTerrain_AfterBothPasses_AndZeroElsewhere()
        {
            // DepthForwardOnly: Stencil { WriteMask 9 Ref 1 Comp Always Pass Replace } over the clear (0) writes 1 & 9 = 1
            // (HDStencilUsage.cs.hlsl: IsUnlit 1, TraceReflectionRay 8 cleared); ForwardOnly's { WriteMask 6 Ref 0 ... } clears
            // RequiresDeferredLighting 2 and SubsurfaceScattering 4 only, so 1 stays. Covered: the prepass's depth is not the clear.
            float[] prepass = Floats(Path.Combine(_out, "hdrp_lit_depth_in.f32"));
            byte[] afterDepth = File.ReadAllBytes(Path.Combine(_out, "hdrp_depth_stencil.u8"));
            byte[] afterForward = File.ReadAllBytes(Path.Combine(_out, "hdrp_lit_stencil.u8"));
            Assert.That(afterDepth.Length, Is.EqualTo(prepass.Length), "one stencil byte per pixel");
            Assert.That(afterForward.Length, Is.EqualTo(prepass.Length), "one stencil byte per pixel");
            int covered = prepass.Count(d => d != 0f);
            int wrongDepth = Enumerable.Range(0, prepass.Length).Count(p => afterDepth[p] != (prepass[p] != 0f ? 1 : 0));
            int wrongForward = Enumerable.Range(0, prepass.Length).Count(p => afterForward[p] != (prepass[p] != 0f ? 1 : 0));
            string values(byte[] s) => string.Join(", ", s.GroupBy(b => b).OrderBy(g => g.Key).Select(g => $"{g.Key}: {g.Count()}"));
            TestContext.Out.WriteLine($"covered {covered}; stencil after DepthForwardOnly {{{values(afterDepth)}}}, after ForwardOnly {{{values(afterForward)}}}");
            Assert.That(covered, Is.GreaterThan(prepass.Length / 5), "pixels the prepass covered");
            Assert.That(wrongDepth, Is.Zero, "pixels whose stencil after DepthForwardOnly is not 1 under the terrain, 0 elsewhere");
            Assert.That(wrongForward, Is.Zero, "pixels whose stencil after ForwardOnly is not 1 under the terrain, 0 elsewhere");
            string depthLog = File.ReadAllText(Path.Combine(_out, "hdrp_depth", "harness.log"));
            string litLog = File.ReadAllText(Path.Combine(_out, "hdrp_lit", "harness.log"));
            Assert.That(depthLog, Does.Contain("--stencil WriteMask 9 Ref 1 Comp Always Pass Replace"), "DepthForwardOnly's ShaderLab Stencil block");
            Assert.That(litLog, Does.Contain("--stencil WriteMask 6 Ref 0 Comp Always Pass Replace").And.Contain("--stencil-in"),
                "ForwardOnly's block, over the prepass's stencil");
        }

        /// <summary>Over the frame: pixels the prepass covered that the forward picture leaves sky (holes), pixels it shades
        /// outside them, pixels whose depth after the forward pass differs from the one it loaded (bits), and the covered count.</summary>
        public static (int Holes, int Outside, int Changed, int Covered) FrameCoverage(string output, RigPng forward)
        {
            float[] prepass = Floats(Path.Combine(output, "hdrp_lit_depth_in.f32")), after = Floats(Path.Combine(output, "hdrp_lit_depth.f32"));
            Assert.That(prepass.Length, Is.EqualTo(forward.Width * forward.Height), "the prepass's depth has one float per pixel");
            int holes = 0, outside = 0, changed = 0, covered = 0;
            for (int p = 0; p < prepass.Length; p++)
            {
                bool depth = prepass[p] != 0f, shaded = !PipelinePassRun.IsSky(forward, p);   // reversed depth: cleared to 0
                covered += depth ? 1 : 0;
                holes += depth && !shaded ? 1 : 0;
                outside += !depth && shaded ? 1 : 0;
                changed += BitConverter.SingleToInt32Bits(prepass[p]) != BitConverter.SingleToInt32Bits(after[p]) ? 1 : 0;
            }
            return (holes, outside, changed, covered);
        }

        static float[] Floats(string path)
        {
            byte[] bytes = File.ReadAllBytes(path);
            var f = new float[bytes.Length / 4];
            Buffer.BlockCopy(bytes, 0, f, 0, f.Length * 4);
            return f;
        }

        [Test]
        public void FiftyKilometresFromTheOrigin_TheCameraRelativePictureIsTheOriginsWithTheSameRounding()
        {
            // hdrp_lit_far: the scene moved 50 km along x and z (float32 positions there step by 4 mm);
            // hdrp_lit_near: at the origin with the object's and camera's positions as float32 rounds them
            // 50 km away. HDRPAdapter's GT_ObjectToWorld subtracts the camera from the translation before
            // adding the rotated position, and both differences are exact (Sterbenz), so the pictures are
            // the same to the bit; mul(M, p) first rounds each vertex at 50 km (measured: 3,813 pixels differ).
            RigPng far = RigPng.Read(Path.Combine(_out, "hdrp_lit_far.png")), near = RigPng.Read(Path.Combine(_out, "hdrp_lit_near.png"));
            int differing = far.PixelsDifferingFrom(near, 1);
            TestContext.Out.WriteLine($"50 km vs origin with the same rounding: pixels differing by more than 1/255: {differing}; " +
                                      $"vs the unrounded origin: {_hdrp.PixelsDifferingFrom(far, 1)}");
            Assert.That(far.PixelsDifferingFrom(_hdrp, 40), Is.LessThan(far.Width * far.Height / 100), "the far picture is the scene's");
            Assert.That(differing, Is.Zero, "pixels of the 50 km picture differing from the origin's with the same rounding");
        }

        [Test]
        public void HdrpsPicture_OverItsScale_IsUrpsPicture_WhereTheirLightingAgrees()
        {
            // Same surface, same sun direction and colour; HDRP's light is lux / pi x exposure (= scale) and
            // its sky probe scale x 0.2 (URP's GT_AMBIENT): HDRP / scale = URP, each 8-bit (HDRP's step is
            // 1/255 / 0.81 after the division), so 2/255 bounds a pixel. HDRP's two passes cover URP's pixels and no others.
            var (largest, over, where) = PipelinePassRun.Difference(_hdrp, _scale, _urp, _covered, 2.0 / 255, "HDRP", "URP");
            var covered = new HashSet<int>(_covered);
            int otherCoverage = _covered.Count(p => PipelinePassRun.IsSky(_hdrp, p)) + Enumerable.Range(0, _urp.Width * _urp.Height)
                .Count(p => !covered.Contains(p) && (!PipelinePassRun.IsSky(_hdrp, p) || !PipelinePassRun.IsSky(_normalBuffer, p)));
            TestContext.Out.WriteLine($"HDRP / {_scale:F4} vs URP over {_covered.Count} pixels: largest {largest * 255:F2}/255, " +
                                      $"channels over 2/255: {over}, coverage differing: {otherCoverage}{where}");
            Assert.That(over, Is.Zero, "channels whose HDRP / scale and URP colours differ by more than 2/255" + where);
            Assert.That(otherCoverage, Is.Zero, "pixels HDRP's ForwardOnly left as sky, or either HDRP pass drew outside URP's terrain");
        }
    }
}
