// The package's shaders on the GPU (lavapipe, through gt-harness) against Core's float mirror of the
// same evaluation path (Runtime/Core/Terrain/TerrainVertex.cs): readback of every vertex at several ranges,
// noise on and off; shared tile edges; vertex counts per range; rendered images. They fail (never
// skip) when the harness, lavapipe, glslang or gt-cli is missing: `gt setup` provides them.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class TerrainGpuTests
    {
        const int Tiles = 8;      // M: 8 x 8 tiles
        const int Factor = 15;    // F: (F+1)^2 = 256 vertices per tile, 16,384 per draw (no split)
        const int VerticesPerRun = Tiles * Tiles * (Factor + 1) * (Factor + 1);

        static readonly NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        static readonly HeightColorSettings Colors = new HeightColorSettings(0.25f, 0.15f, 24f);

        // (name, range): the whole terrain; a quarter whose corner is on no grid line (c != a);
        // a small range straddling the patch lines x = y = 0.4; a narrow one (width 1e-3, below
        // RangeOrigin.DeepWidth, so it is drawn relative to a snapped origin).
        static readonly (string name, TerrainRange range)[] Ranges =
        {
            ("full", new TerrainRange(0, 0, 1, 1)),
            ("quarter", new TerrainRange(0.3, 0.15, 0.8, 0.65)),
            ("straddle", new TerrainRange(0.37, 0.35, 0.43, 0.41)),
            ("narrow", new TerrainRange(0.6131, 0.2217, 0.6141, 0.2227)),
        };

        string _work, _spirv, _cli, _gridPath;
        PatchGrid _grid;
        readonly Dictionary<string, ReadbackRun> _runs = new Dictionary<string, ReadbackRun>();

        [OneTimeSetUp]
        public void BuildGridAndShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-terrain");
            _cli = ReadbackRun.Cli();
            _grid = ReadbackRun.DemoGrid(_work, out _gridPath);
            _spirv = ReadbackRun.CompileVariants(_work, "readback", "readback+noise", "noise+height_color");
        }

        /// <summary>Draws the grid at <paramref name="range"/> with M x M tiles at uniform factor F and reads every vertex back.</summary>
        ReadbackRun Readback(string name, TerrainRange range, bool noise)
        {
            string key = name + (noise ? "+noise" : "");
            if (_runs.TryGetValue(key, out ReadbackRun cached)) return cached;
            var p = ReadbackRun.UniformParams(_grid, range, RangeOrigin.For(range), Tiles, Factor, Noise);
            ReadbackRun run = ReadbackRun.Draw(Path.Combine(_work, key), _spirv, _grid, p, noise ? Noise : (NoiseSettings?)null);
            Assert.That(run.VertexCount, Is.EqualTo(VerticesPerRun));
            _runs[key] = run;
            return run;
        }

        [Test]
        public void GpuReadbackMatchesCoreFloatPathOnEveryPatchAtSeveralRanges()
        {
            double extent = ReadbackRun.TerrainExtent(_grid);
            int total = 0, unmatched = 0, bitPos = 0, bitNormal = 0, qEqual = 0, nan = 0;
            double maxPos = 0, maxNormal = 0, maxRef = 0;
            foreach (bool noise in new[] { false, true })
            {
                int totalThis = 0;
                foreach (var (name, range) in Ranges)
                {
                    ReadbackComparison c = Readback(name, range, noise).Compare();
                    c.MaxPosition /= extent;
                    c.MaxReference /= extent;
                    TestContext.Out.WriteLine(
                        "{0,-16} vertices {1}, patches {2}, tess found {3}, q equal {4}, position bit-identical {5}, normal bit-identical {6}, " +
                        "max |gpu - core| / extent {7:G3}, max |normal diff| {8:G3}, max |core float - double| / extent {9:G3}",
                        name + (noise ? "+noise" : ""), c.Vertices, c.Patches.Count, c.Vertices - c.Unmatched, c.QEqual,
                        c.PositionBitIdentical, c.NormalBitIdentical, c.MaxPosition, c.MaxNormal, c.MaxReference);
                    if (name == "full")
                        Assert.That(c.Patches.Count, Is.EqualTo(_grid.PatchCount), "the full range reaches every patch");
                    if (name == "straddle")
                        Assert.That(c.Patches.Count, Is.EqualTo(4), "the straddling range reaches the four patches around (0.4, 0.4)");
                    total += c.Vertices; totalThis += c.Vertices; unmatched += c.Unmatched; bitPos += c.PositionBitIdentical;
                    bitNormal += c.NormalBitIdentical; qEqual += c.QEqual; nan += c.Nan;
                    maxPos = Math.Max(maxPos, c.MaxPosition); maxNormal = Math.Max(maxNormal, c.MaxNormal); maxRef = Math.Max(maxRef, c.MaxReference);
                }
                Assert.That(totalThis, Is.GreaterThanOrEqualTo(10000), "vertices compared with noise " + (noise ? "on" : "off"));
            }
            TestContext.Out.WriteLine(
                "GPU vs Core float: {0} vertices, largest position difference {1:G3} of the terrain's extent ({2:G4}), largest normal difference {3:G3}; " +
                "{4} positions and {5} normals bit-identical, {6} q equal; Core float vs double reference {7:G3} of the extent",
                total, maxPos, extent, maxNormal, bitPos, bitNormal, qEqual, maxRef);
            Assert.That(nan, Is.EqualTo(0), "readback slots never written");
            Assert.That(unmatched, Is.EqualTo(0), "vertices whose tess coordinate could not be recovered from q and u, v");
            Assert.That(qEqual, Is.EqualTo(total), "global points q");
            Assert.That(maxPos, Is.LessThan(1e-5), "largest GPU-vs-Core position difference relative to the terrain's extent");
            Assert.That(maxNormal, Is.LessThan(1e-4), "largest GPU-vs-Core normal difference");
            Assert.That(maxRef, Is.LessThan(1e-5), "Core float vs double reference, relative to the extent");
        }

        [Test]
        public void VerticesOnSharedTileEdgesAreBitIdenticalFromBothSides()
        {
            int pairs = 0, differing = 0;
            foreach (bool noise in new[] { false, true })
                foreach (var (name, range) in Ranges)
                {
                    var (p, d) = Readback(name, range, noise).SharedEdges();
                    pairs += p;
                    differing += d;
                }
            TestContext.Out.WriteLine("shared tile edges: {0} vertex pairs, {1} differ in any bit of position, normal, q or u, v", pairs, differing);
            // Per run: M (M - 1) shared edges each way, F + 1 vertices on each.
            Assert.That(pairs, Is.EqualTo(2 * Ranges.Length * 2 * Tiles * (Tiles - 1) * (Factor + 1)));
            Assert.That(differing, Is.EqualTo(0));
        }

        /// <summary>
        /// Anchored tiles (TileLattice) through the domain stage: the range panned by part of a cell
        /// (and, deep-zoom, from a snapped origin) over the lattice anchored at its start. Every vertex
        /// of the (M + 1)^2 tiles is Core's, inside the range, and shared edges are bit-identical.
        /// </summary>
        [Test]
        public void AnchoredTilesReadBackCoresVerticesWatertight()
        {
            double extent = ReadbackRun.TerrainExtent(_grid);
            foreach (var (name, lattice) in new[] { ("quarter", Ranges[1].range), ("narrow", Ranges[3].range) })
                foreach (bool noise in new[] { false, true })
                {
                    // A pan of 0.37 cell in x and 0.81 in y: the first cell stays k0 = 0, so slot order is tile order.
                    double cx = lattice.Width / Tiles, cy = lattice.Height / Tiles;
                    var range = new TerrainRange(lattice.c + 0.37 * cx, lattice.d + 0.81 * cy, lattice.g + 0.37 * cx, lattice.h + 0.81 * cy);
                    RangeOrigin origin = RangeOrigin.For(lattice);
                    var p = ReadbackRun.UniformParams(_grid, range, origin, Tiles, Factor, Noise);
                    RangeMapping.EncodeRange(lattice, origin, out Float4 latticeF, out _);
                    p = p.WithTileLattice(latticeF);
                    string key = "anchored-" + name + (noise ? "+noise" : "");
                    ReadbackRun run = ReadbackRun.Draw(Path.Combine(_work, key), _spirv, _grid, p, noise ? Noise : (NoiseSettings?)null);
                    Assert.That(run.Tiles, Is.EqualTo(Tiles + 1), key);
                    ReadbackComparison c = run.Compare();
                    var (pairs, differing) = run.SharedEdges();
                    TestContext.Out.WriteLine("{0,-24} vertices {1}, tess found {2}, q equal {3}, max |gpu - core| / extent {4:G3}, max |normal diff| {5:G3}; shared edges {6} pairs, {7} differ",
                        key, c.Vertices, c.Vertices - c.Unmatched, c.QEqual, c.MaxPosition / extent, c.MaxNormal, pairs, differing);
                    Assert.That(c.Nan, Is.EqualTo(0), key);
                    Assert.That(c.Vertices, Is.EqualTo((Tiles + 1) * (Tiles + 1) * (Factor + 1) * (Factor + 1)), key);
                    Assert.That(c.Unmatched, Is.EqualTo(0), key + ": tess coordinates recovered through Core's anchored mapping");
                    Assert.That(c.QEqual, Is.EqualTo(c.Vertices), key + ": global points q");
                    Assert.That(c.MaxPosition / extent, Is.LessThan(1e-5), key);
                    Assert.That(c.MaxNormal, Is.LessThan(1e-4), key);
                    Assert.That(pairs, Is.EqualTo(2 * (Tiles + 1) * Tiles * (Factor + 1)), key + ": M (M + 1) shared edges each way");
                    Assert.That(differing, Is.EqualTo(0), key + ": shared edges bit-identical");
                    // Every vertex lies in the range (the first tile starts at c, the last ends at g): the
                    // read-back q is rounded to float, so within 2e-7 (three of its steps near 0.6).
                    Float4 r = p.range;
                    double ox = (double)p.rangeOrigin.x + p.rangeOrigin.z, oy = (double)p.rangeOrigin.y + p.rangeOrigin.w;
                    for (int k = 0; k < run.VertexCount; k++)
                    {
                        double qx = run.Readback[12 * k + 8], qy = run.Readback[12 * k + 9];
                        Assert.That(qx >= ox + r.x - 2e-7 && qx <= ox + r.z + 2e-7 && qy >= oy + r.y - 2e-7 && qy <= oy + r.w + 2e-7,
                                    Is.True, $"{key}: vertex {k} at ({qx:R}, {qy:R}) outside the range {r} + origin ({ox:R}, {oy:R})");
                    }
                }
        }

        [Test]
        public void VertexCountIsTheSameAtEveryRange()
        {
            var counts = new List<long>();
            foreach (var (name, range) in Ranges)
            {
                HarnessRun h = Readback(name, range, true).Harness;
                long tes = h.Long("stat", "tessellation_evaluation_shader_invocations");
                // Triangles entering the clipper (clipping_primitives counts what leaves it, which
                // grows where the view's edges split triangles).
                long triangles = h.Long("stat", "clipping_invocations");
                TestContext.Out.WriteLine("{0,-10} tess evaluation invocations {1}, triangles {2}", name, tes, triangles);
                Assert.That(triangles, Is.EqualTo(2L * Tiles * Tiles * Factor * Factor), name + ": 2 M^2 F^2 triangles");
                counts.Add(tes);
            }
            Assert.That(counts.Distinct().Count(), Is.EqualTo(1), "tess evaluation invocations differ between ranges: " + string.Join(", ", counts));
            Assert.That(counts[0], Is.EqualTo((long)VerticesPerRun), "M^2 (F+1)^2 on lavapipe (its statistics are exact)");
        }

        // ---- images -----------------------------------------------------------------------------

        /// <summary>Renders the shipped look (noise + height colour, adaptive factors) in the zoom view at range (0, 0, g, g).</summary>
        (HarnessRun run, byte[] rgb) Render(double g)
        {
            string dir = Path.Combine(_work, "image_g" + g.ToString(System.Globalization.CultureInfo.InvariantCulture));
            string r = "0,0," + g.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + "," + g.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
            ReadbackRun.Exec(_cli, new[] { "pack", "--grid", _gridPath, "--range", r, "--tiles", "8", "--width", "160", "--height", "120", "--out", dir }, null);
            string v = Path.Combine(_spirv, "noise+height_color");
            string png = Path.Combine(dir, "image.png");
            HarnessRun h = HarnessRun.Harness("--vert", Path.Combine(v, "vert.spv"), "--tesc", Path.Combine(v, "tesc.spv"),
                "--tese", Path.Combine(v, "tese.spv"), "--frag", Path.Combine(v, "frag.spv"), "--buffers", dir,
                "--patches", "64", "--width", "160", "--height", "120", "--png", png, "--stats", "--device", "llvmpipe");
            h.AssertSucceeded();
            return (h, DecodeRgb(png, 160, 120));
        }

        [Test]
        public void RenderedImageIsTerrainAndChangesWithTheRange()
        {
            var (fullRun, full) = Render(1.0);
            var (zoomRun, zoom) = Render(0.2);
            long total = 160 * 120;
            foreach (var (name, run, rgb) in new[] { ("g = 1", fullRun, full), ("g = 0.2", zoomRun, zoom) })
            {
                long nonsky = run.Long("image", "nonsky_pixels");
                int colours = Enumerable.Range(0, (int)total).Select(i => (rgb[3 * i] << 16) | (rgb[3 * i + 1] << 8) | rgb[3 * i + 2]).Distinct().Count();
                TestContext.Out.WriteLine("{0}: {1} of {2} pixels not sky, {3} distinct colours, {4} vertices, hash {5:x16}",
                    name, nonsky, total, colours, run.Long("stat", "tessellation_evaluation_shader_invocations"), Fnv(rgb));
                Assert.That(nonsky, Is.GreaterThan(total / 5), name + ": the terrain covers a fifth of the image at least");
                Assert.That(colours, Is.GreaterThan(100), name + ": lit, shaded terrain has many colours");
            }
            int changed = Enumerable.Range(0, (int)total).Count(i => full[3 * i] != zoom[3 * i] || full[3 * i + 1] != zoom[3 * i + 1] || full[3 * i + 2] != zoom[3 * i + 2]);
            TestContext.Out.WriteLine("pixels that differ between g = 1 and g = 0.2: {0} of {1}", changed, total);
            Assert.That(Fnv(full), Is.Not.EqualTo(Fnv(zoom)));
            Assert.That(changed, Is.GreaterThan(total / 10), "zooming changes the picture");
        }

        static ulong Fnv(byte[] b)
        {
            ulong h = 14695981039346656037ul;
            foreach (byte x in b) { h ^= x; h *= 1099511628211ul; }
            return h;
        }

        /// <summary>RGB bytes of a harness PNG of the given size.</summary>
        static byte[] DecodeRgb(string path, int width, int height)
        {
            RigPng png = RigPng.Read(path);
            Assert.That((png.Width, png.Height), Is.EqualTo((width, height)), path);
            var rgb = new byte[3 * width * height];
            for (int p = 0; p < width * height; p++)
                for (int c = 0; c < 3; c++)
                    rgb[3 * p + c] = png.Rgba[4 * p + c];
            return rgb;
        }
    }
}
