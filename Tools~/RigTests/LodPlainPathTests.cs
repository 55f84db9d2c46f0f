// The levels' plain path (internals.md, "The levels' plain path"), Core's float mirror of the domain
// stage (which MirrorCheckTests and the GPU tests keep equal to the HLSL): over the ground views of
// 100 km and 1,000 km, every vertex the switch puts on the plain path must lie within the bound
// PlainPathError of the precise path's output (less the precise path's own offset p(O) - p_c(O), O's
// octaves too fine for the vertex), so within a quarter pixel at its pixel scale; the near
// vertices keep the precise path bit for bit; and both paths are drawn (the switch is not trivially off).
using System;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class LodPlainPathTests
    {
        const int Samples = 5;   // tess points a tile and axis

        [TestCase(100000.0, 1.0)]
        [TestCase(1000000.0, 1.0)]
        public void PlainVerticesStayWithinTheBound(double terrainMeters, double boundScale)
        {
            var (plain, precise, bound) = Check(terrainMeters, boundScale);
            Assert.That(plain, Is.GreaterThan(0), "no vertex on the plain path");
            Assert.That(precise, Is.GreaterThan(0), "no vertex on the precise path");
            TestContext.Progress.WriteLine(FormattableString.Invariant(
                $"lod plain path {terrainMeters / 1000:F0} km: {plain} plain, {precise} precise vertices; largest |plain - precise| / e = {bound:F3}"));
        }

        /// <summary>A bound 100 times tighter than derived draws vertices on the plain path nearer than it holds: the check must see it.</summary>
        [Test]
        public void ATooTightBoundIsCaught()
        {
            Assert.That(() => Check(1000000.0, 0.01), Throws.InstanceOf<AssertionException>());
        }

        static (int plain, int precise, double largest) Check(double terrainMeters, double boundScale)
        {
            PatchGrid grid = HardCaseGrids.Fitted();
            LodScene on = new LodScene { TerrainMeters = terrainMeters }.Build(grid);
            float e = on.Inputs.Params.noiseOctaves.w * (float)boundScale;
            if (boundScale != 1.0)
            {
                TerrainParams p = on.Inputs.Params;
                p.noiseOctaves.w = e;
                on.Inputs = on.Inputs.WithParams(p);
            }
            LodScene off = new LodScene { TerrainMeters = terrainMeters, PlainPath = false }.Build(grid);
            Assert.That(e, Is.GreaterThan(0f), "the scene sends no plain-path bound");
            Assert.That(off.Inputs.Params.noiseOctaves.w, Is.EqualTo(0f));
            Float4x4 clip = on.Camera.ObjectToClipFloat();
            var screen = new Float2(on.Width, on.Height);
            int plain = 0, precise = 0;
            double largest = 0.0;
            for (int patch = 0; patch < on.Patches; patch++)
                for (int j = 0; j < Samples; j++)
                    for (int i = 0; i < Samples; i++)
                    {
                        double s = i / (Samples - 1.0), t = j / (Samples - 1.0);
                        double[] a = on.DrawnObjectPoint(patch, s, t), b = off.DrawnObjectPoint(patch, s, t);
                        // The switch's own test, on the plain output without noise (as the stage makes it).
                        float k = PixelScale(on, clip, screen, patch, s, t, out double fineOctavesAtO);
                        // The precise path outputs p_c(q) - p_c(O) at the vertex's count c, the renderer adds
                        // p(O) at every octave; the plain path subtracts that p(O) itself, so it lacks the
                        // precise path's offset p(O) - p_c(O) (O's octaves too fine for this vertex).
                        double h = a[1] - (b[1] - fineOctavesAtO);
                        double d = Math.Sqrt((a[0] - b[0]) * (a[0] - b[0]) + h * h + (a[2] - b[2]) * (a[2] - b[2]));
                        if (TerrainVertex.UsesPlainPath(on.Inputs.Params, k))
                        {
                            plain++;
                            largest = Math.Max(largest, d / e);
                            Assert.That(d, Is.LessThanOrEqualTo(e), FormattableString.Invariant(
                                $"draw patch {patch} at ({s}, {t}): plain and precise outputs {d:G3} apart (x {a[0] - b[0]:G3}, height {h:G3}, y {a[2] - b[2]:G3}), above the bound {e:G3} ({d * k:G3} px at {k:G3} px a unit)"));
                            Assert.That(d * k, Is.LessThanOrEqualTo(TerrainVertex.PlainPathPixels), FormattableString.Invariant(
                                $"draw patch {patch} at ({s}, {t}): plain and precise outputs {d * k:G3} px apart"));
                        }
                        else
                        {
                            precise++;
                            Assert.That(a, Is.EqualTo(b), $"draw patch {patch} at ({s}, {t}): a precise vertex moved");
                        }
                    }
            return (plain, precise, largest);
        }

        /// <summary>The pixel scale at the plain output S(q) - S(O) of draw patch p's point (s, t), as the switch takes it.</summary>
        static float PixelScale(LodScene scene, Float4x4 clip, Float2 screen, int patch, double s, double t, out double fineOctavesAtO)
        {
            int level = LodTiles.LevelOfPatch(patch, scene.Tiles), slot = LodTiles.SlotOfPatch(patch, scene.Tiles);
            var r = new Float4(scene.Tail[4 + 4 * level], scene.Tail[5 + 4 * level], scene.Tail[6 + 4 * level], scene.Tail[7 + 4 * level]);
            TerrainPoint q = RangeMapping.ToTerrainPoint(r, scene.Inputs.Params.rangeOrigin, scene.Tiles, slot % scene.Tiles, slot / scene.Tiles, (float)s, (float)t);
            TerrainSurfacePoint sp = TerrainVertex.EvaluateSurfaceAt(scene.Inputs, q);
            Float4 o = scene.Inputs.Params.originSurface;
            Float3 plainSurface = sp.position - new Float3(o.x, o.y, o.z);
            // p(O) at every octave minus p_c(O) at the precise vertex's count c, in double.
            TerrainParams p = scene.Inputs.Params;
            Float3 precise = TerrainVertex.OutputSurfacePosition(scene.Inputs, sp, TerrainKeywords.Noise);
            float c = TerrainInputs.NoiseOctaveCountAt(p, TessellationPolicy.PixelsPerUnit(clip, TerrainVertex.TerrainToObject(precise), screen));
            Double2 origin = RelativeSurface.OriginPoint(p.rangeOrigin) is var op ? new Double2((double)op.originHi.x + op.local.x, (double)op.originHi.y + op.local.y) : default;
            fineOctavesAtO = OctaveNoise.Evaluate(origin.x, origin.y, scene.DrawnNoise, TerrainVertex.OutputOffsetOctaves(p), out _)
                           - OctaveNoise.Evaluate(origin.x, origin.y, scene.DrawnNoise, c, out _);
            return TessellationPolicy.PixelsPerUnit(clip, TerrainVertex.TerrainToObject(plainSurface), screen);
        }
    }
}
