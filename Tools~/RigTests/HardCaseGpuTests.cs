// The named hard cases on the GPU (lavapipe, readback variant) against Core's float mirror of the
// shaders (TerrainVertex.cs), each with its own stated bound; watertightness under random factors
// and ranges; a GPU property test over random ranges and grids; deep-zoom jitter through the
// harness. Every case asserts no NaN or infinity in any read-back float. The grids are those of
// Tests/Core/HardCaseTests (HardCaseGrids). Helpers: ReadbackRun.cs.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class HardCaseGpuTests
    {
        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        string _work, _spirv;
        PatchGrid _fitted;
        int _runCount;

        /// <summary>Named GPU hard cases that passed (printed by <see cref="Summary"/>).</summary>
        static int s_named;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-hardcases");
            _spirv = ReadbackRun.CompileVariants(_work, "readback", "readback+noise");
            _fitted = HardCaseGrids.Fitted();
        }

        /// <summary>A fresh folder per run, named after the case (letters and digits only: the harness prints paths between spaces).</summary>
        string NextDir(string name) =>
            Path.Combine(_work, (_runCount++).ToString("D3") + "-" + new string(name.Select(ch => char.IsLetterOrDigit(ch) ? ch : '_').ToArray()));

        /// <summary>One patch as a 1 x 1 grid over the unit square (its own control points, no neighbours).</summary>
        static PatchGrid OnePatch(GregoryPatch p)
        {
            PatchGrid g = PatchGrid.CreateFlat(1, 1);
            for (int k = 0; k < GregoryPatch.SlotCount; k++) g.Patches[0][k] = p[k];
            return g;
        }

        /// <summary>
        /// Draws one case, asserts no NaN/inf in any read-back float, every tess coordinate recovered,
        /// shared tile edges bit-identical and GPU vs Core float within <paramref name="bound"/>
        /// (terrain units; the figure printed).
        /// </summary>
        ReadbackRun Case(string name, PatchGrid grid, TerrainRange range, int tiles, int factor, double bound,
                         NoiseSettings? noise = null, RangeOrigin? origin = null, float noiseVerticesAcross = 0f, double normalBound = 1e-3)
        {
            var p = ReadbackRun.UniformParams(grid, range, origin ?? RangeOrigin.For(range), tiles, factor, noise ?? Noise, noiseVerticesAcross);
            ReadbackRun run = ReadbackRun.Draw(NextDir(name), _spirv, grid, p, noise);
            Assert.That(run.NonFinite(), Is.EqualTo(0), name + ": NaN/inf (or unwritten) read-back floats");
            ReadbackComparison c = run.Compare();
            var (pairs, differing) = run.SharedEdges();
            TestContext.Out.WriteLine(FormattableString.Invariant(
                $"gpu hard case {name,-40} bound {bound,-9:G3} |gpu - core float| {c.MaxPosition:G3}, normal {c.MaxNormal:G3}, core float vs double {c.MaxReference:G3}, {c.Vertices} vertices, {c.Patches.Count} patches, edge pairs differing {differing} of {pairs}"));
            Assert.That(c.Unmatched, Is.EqualTo(0), name + ": tess coordinates not recovered");
            Assert.That(differing, Is.EqualTo(0), name + ": shared tile edge vertices differ");
            Assert.That(c.MaxPosition, Is.LessThanOrEqualTo(bound), name + ": GPU vs Core float");
            Assert.That(c.MaxNormal, Is.LessThanOrEqualTo(normalBound), name + ": normals");
            s_named++;
            return run;
        }

        // ------------------------------------------------------------------ corners

        [Test]
        public void CornersAtTheExactPoints()
        {
            // 1 x 1 tile at factor 1 over a patch region: the 4 vertices are the patch corners exactly
            // (tess 0 and 1 give q = c and g), where the surface is the corner control point.
            PatchGrid g = _fitted;
            double worst = 0;
            foreach (var (i, j) in new[] { (0, 0), (2, 1), (4, 4) })
            {
                Region r = g.RegionOf(i, j);
                ReadbackRun run = Case($"corners of patch ({i},{j})", g, new TerrainRange(r.a, r.b, r.e, r.f), 1, 1, 0.0);
                GregoryPatch p = g.Patches[j * g.Columns + i];
                foreach (var (row, col, slot) in new[] { (0, 0, 0), (0, 1, 12), (1, 0, 3), (1, 1, 15) })
                {
                    int o = 12 * run.Index(0, 0, row, col);
                    var corner = new Float3((float)p[slot].x, (float)p[slot].y, (float)p[slot].z);
                    // the patch that owns the corner point may be the neighbour (FindPatch rule); the
                    // GPU forms the point as R_p + (P - R_p) (GpuLayout's relative points), two roundings
                    // of numbers below 1: within 6e-8 of the control point
                    worst = Math.Max(worst, ReadbackRun.Distance(new Float3(run.Readback[o], run.Readback[o + 2], run.Readback[o + 1]), corner));
                }
            }
            TestContext.Out.WriteLine($"gpu corners: largest |gpu - corner control point| {worst:G3}");
            Assert.That(worst, Is.LessThanOrEqualTo(6e-8), "corner vertices are the control points to float's rounding");
        }

        [Test]
        public void NearCornerPoints()
        {
            // Ranges 2e-7 wide centred on corners (terrain corners and a corner shared by 4 patches):
            // factor 2 puts the middle vertex on the corner, the others 1e-7 away along 8 directions.
            PatchGrid g = _fitted;
            double x1 = g.XLines[2], y1 = g.YLines[3];
            foreach (var (cx, cy) in new[] { (0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (x1, y1) })
            {
                double c = Math.Min(Math.Max(cx - 1e-7, 0), 1 - 2e-7), d = Math.Min(Math.Max(cy - 1e-7, 0), 1 - 2e-7);
                // relative output at these widths: differences ~1e-7, float keeps ~1e-14 of them
                Case(FormattableString.Invariant($"near corner ({cx:G3},{cy:G3}) 1e-7"), g, new TerrainRange(c, d, c + 2e-7, d + 2e-7), 1, 2, 1e-12);
            }
        }

        // ------------------------------------------------------------------ degenerate patches

        [Test]
        public void CollapsedEdge()
        {
            GregoryPatch p = TestPatches.Random(5);
            for (int j = 0; j < 4; j++) p[GregoryPatch.Slot(0, j)] = p[0];
            Case("collapsed edge", OnePatch(p), TerrainRange.full, 4, 8, 1e-6);
        }

        [Test]
        public void InteriorPairsFarApart()
        {
            GregoryPatch p = TestPatches.Random(6);
            foreach (int s in new[] { GregoryPatch.P111, GregoryPatch.P121, GregoryPatch.P211, GregoryPatch.P221 })
                p[s] = p[s] + new Double3(1e3, -1e3, 1e3);
            Case("interior pairs 1e3 apart", OnePatch(p), TerrainRange.full, 4, 8, 1e3 * 1e-6);
        }

        [TestCase(1e-9, TestName = "NearlyFlat")]
        [TestCase(1e6, TestName = "NearlyVertical")]
        public void FlatOrVertical(double heightScale)
        {
            GregoryPatch p = TestPatches.Random(7);
            for (int k = 0; k < 20; k++) p[k] = new Double3(p[k].x, p[k].y, p[k].z * heightScale);
            Case($"height scale {heightScale:G3}", OnePatch(p), TerrainRange.full, 4, 8, 1e-6 * Math.Max(1, heightScale));
        }

        // ------------------------------------------------------------------ regions and ranges

        [Test]
        public void ExtremeAspectRatioRegion() =>
            Case("region 1:1000", HardCaseGrids.WithLines(new[] { 0.0, 0.4, 0.401, 1.0 }, new[] { 0.0, 1.0 }),
                 new TerrainRange(0.399, 0.0, 0.402, 1.0), 4, 16, 1e-6);

        [Test]
        public void TinyRegion() =>
            Case("region 1e-6 of the terrain", HardCaseGrids.WithLines(new[] { 0.0, 0.5, 0.5 + 1e-6, 1.0 }, new[] { 0.0, 0.5, 0.5 + 1e-6, 1.0 }),
                 // the CPU case's bound: float grid lines 0.5 + 1e-6 are 6% off the double ones, and
                 // lavapipe's division differs from .NET's in the last bits of u there (~1e-7 seen).
                 // Normals are held to the default bound: summing the points' derivative terms
                 // cancelled (normals 0.044 apart); GregoryEvaluate sums differences now (1.1e-7).
                 new TerrainRange(0.5 - 1e-6, 0.5 - 1e-6, 0.5 + 2e-6, 0.5 + 2e-6), 3, 8, 1e-7);

        [Test]
        public void RangeTouchingTheTerrainEdge()
        {
            Case("range touching the terrain edge", _fitted, new TerrainRange(0.9, 0.0, 1.0, 0.1), 4, 8, 1e-6);
            Case("whole terrain (every edge)", _fitted, TerrainRange.full, 4, 8, 1e-6);
        }

        [Test]
        public void RangeOfOnePatch()
        {
            Region r = _fitted.RegionOf(2, 1);
            ReadbackRun run = Case("range = one patch", _fitted, new TerrainRange(r.a, r.b, r.e, r.f), 2, 16, 1e-6);
            Assert.That(run.Compare().Patches.Count, Is.LessThanOrEqualTo(4), "the range's edge vertices belong to the patch or its neighbours");
        }

        [Test]
        public void RangeSmallerThanOneVertexSpacing() =>
            // 1e-9 wide: far below a vertex spacing of a whole-terrain view; relative output
            Case("range 1e-9 wide", _fitted, new TerrainRange(0.3, 0.7, 0.3 + 1e-9, 0.7 + 1e-9), 1, 16, 1e-15);

        // ------------------------------------------------------------------ large coordinates

        [TestCase(1e5, TestName = "TerrainOf1e5Metres")]
        [TestCase(1e6, TestName = "TerrainOf1e6Metres")]
        public void LargeTerrainCoordinates(double metres)
        {
            // The GPU layout carries any float control points; a terrain in metres is its control
            // points scaled (x, y and height). Float keeps ~1e-7 of the scale.
            GregoryPatch p = TestPatches.Random(8);
            for (int k = 0; k < 20; k++) p[k] = p[k] * metres;
            Case($"terrain of {metres:G3} m", OnePatch(p), TerrainRange.full, 4, 8, 1e-6 * metres);
        }

        // ------------------------------------------------------------------ noise

        [Test]
        public void NoiseAtLatticeCoordinate1e6With12Octaves()
        {
            // top octave frequency 512 * 2^11 = 1,048,576 cells across the terrain: lattice coordinates
            // ~1e6 near q ~ 1; a huge verticesAcross keeps all 12 octaves on.
            var s = new NoiseSettings(0.01f, 512f, 2f, 2f, 12);
            Case("noise 12 octaves, lattice ~1e6", _fitted, new TerrainRange(0.9, 0.9, 0.95, 0.95), 4, 8, 1e-6, s, null, 1e9f);
            // and at deep zoom (relative noise, p(q) - p(O)): 1e-5 of the 1e-6 width (0.008 px of an
            // 800-px view); lavapipe's and .NET's float rounding differ in places (~5e-12 seen)
            Case("noise 12 octaves, deep zoom 1e-6", _fitted, new TerrainRange(0.7, 0.7, 0.7 + 1e-6, 0.7 + 1e-6), 4, 8, 1e-11, s, null, 1e9f);
        }

        // ------------------------------------------------------------------ tessellation

        [Test]
        public void Factor1() => Case("factor 1 (8 x 8 tiles)", _fitted, new TerrainRange(0.1, 0.2, 0.7, 0.8), 8, 1, 1e-6);

        [Test]
        public void Factor64()
        {
            // 4 x 4 tiles at 64: 67,600 vertices, over lavapipe's 65,536: the harness splits the draw.
            ReadbackRun run = Case("factor 64 (4 x 4 tiles, split draw)", _fitted, new TerrainRange(0.1, 0.2, 0.7, 0.8), 4, 64, 1e-6);
            int draws = run.Harness.Stdout.Split('\n').Count(l => l.StartsWith("draw ", StringComparison.Ordinal));
            TestContext.Out.WriteLine($"factor 64: {draws} draws");
            Assert.That(draws, Is.GreaterThan(1), "the split covers the 65,536-vertex limit");
        }

        /// <summary>
        /// Adaptive mode (factors from the camera) with the camera at <paramref name="eye"/>: the readback
        /// variant with _Tess.w = 0 writes every vertex of tile t into slot t (the index uses factor 0),
        /// so each drawn tile leaves one vertex: no NaN/inf there, and it matches Core at its own q.
        /// </summary>
        void AdaptiveCamera(string name, Double3 eye, Double3 target)
        {
            const int tiles = 8;
            var p = TerrainParams.Create(_fitted, TerrainRange.full, RangeOrigin.zero, new TessellationSettings(tiles, 64f, 8f, 0f),
                Noise, new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f));
            var inputs = TerrainInputs.Create(_fitted, p);
            string dir = NextDir(name);
            ReadbackRun.WriteBuffers(dir, inputs, ReadbackRun.PerspectiveCamera(eye, target, 60, 128, 96, 1e-4, 10));
            string rb = Path.Combine(dir, "readback.f32");
            var args = new List<string>(ReadbackRun.Stages(_spirv, "readback+noise"));
            args.AddRange(new[] { "--buffers", dir, "--patches", (tiles * tiles).ToString(), "--width", "128", "--height", "96", "--device", "llvmpipe",
                                  "--stats", "--readback", rb, "--readback-floats", (12 * tiles * tiles).ToString(), "--readback-fill", "zero" });
            HarnessRun h = HarnessRun.Harness(args.ToArray());
            h.AssertSucceeded();
            float[] v = ReadbackRun.ReadFloats(rb);
            int nonFinite = v.Count(x => !float.IsFinite(x)), written = 0;
            double worst = 0;
            for (int t = 0; t < tiles * tiles; t++)
            {
                int o = 12 * t;
                if (v[o + 3] != 1f) continue;   // culled tile: never written
                written++;
                TerrainVertexOutput core = TerrainVertex.EvaluateAt(inputs, TerrainPoint.FromFloat(new Float2(v[o + 8], v[o + 9])), TerrainKeywords.Noise);
                worst = Math.Max(worst, ReadbackRun.Distance(new Float3(v[o], v[o + 1], v[o + 2]), core.PositionOS));
            }
            long tes = h.Long("stat", "tessellation_evaluation_shader_invocations"), nonsky = h.Long("image", "nonsky_pixels");
            TestContext.Out.WriteLine($"gpu hard case {name,-40} bound 1e-6      |gpu - core float| {worst:G3}, tiles drawn {written} of {tiles * tiles}, " +
                                      $"tess evaluations {tes}, non-sky pixels {nonsky}, non-finite floats {nonFinite}");
            Assert.That(nonFinite, Is.EqualTo(0), name + ": NaN/inf in the readback");
            Assert.That(written, Is.GreaterThan(0), name + ": some tiles are drawn");
            Assert.That(tes, Is.GreaterThan(0));
            Assert.That(nonsky, Is.GreaterThan(0), name + ": the terrain is in the image");
            Assert.That(worst, Is.LessThanOrEqualTo(1e-6), name + ": GPU vs Core float at the read-back q");
            s_named++;
        }

        [Test]
        public void CameraInsideTheBoundingBox()
        {
            double z = RelativeSurface.SurfaceAt(_fitted, new Double2(0.45, 0.55)).z;
            // object space is (x, height, y): an eye just above the surface, inside the terrain's box
            AdaptiveCamera("adaptive, camera inside the box", new Double3(0.45, z + 0.002, 0.55), new Double3(0.9, z, 0.8));
        }

        [Test]
        public void CameraOnAPatchEdge()
        {
            double x = _fitted.XLines[2], y = 0.5;
            double z = RelativeSurface.SurfaceAt(_fitted, new Double2(x, y)).z;
            // the eye exactly on the surface over the grid line x = XLines[2]: tile corners at distance ~0
            AdaptiveCamera("adaptive, camera on a patch edge", new Double3(x, z, y), new Double3(x + 0.3, z - 0.05, y + 0.1));
        }

        [OneTimeTearDown]
        public void Summary() => TestContext.Out.WriteLine($"named GPU hard cases passed: {s_named}");
    }
}
