// The package's shaders on the GPU (lavapipe, through gt-harness) against Core's float mirror of the
// same evaluation path (Runtime/Core/TerrainVertex.cs): readback of every vertex at several ranges,
// noise on and off; shared tile edges; vertex counts per range; rendered images. They fail (never
// skip) when the harness, lavapipe, glslang or gt-cli is missing: `gt setup` provides them.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.IO.Compression;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
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

        string _root, _work, _spirv, _cli, _gridPath;
        PatchGrid _grid;
        readonly Dictionary<string, Run> _runs = new Dictionary<string, Run>();

        sealed class Run
        {
            public string Name;
            public TerrainInputs Inputs;
            public TerrainKeywords Keywords;
            public float[] Readback;
            public HarnessRun Harness;
        }

        [OneTimeSetUp]
        public void BuildGridAndShaders()
        {
            _root = HarnessRun.PackageRoot();
            Assert.That(File.Exists(HarnessRun.HarnessPath()), Is.True, "gt-harness not built at " + HarnessRun.HarnessPath() + " (run Tools~/gt setup)");
            Assert.That(File.Exists(HarnessRun.LavapipeIcd), Is.True, "lavapipe is not installed (" + HarnessRun.LavapipeIcd + ")");
            _cli = Path.Combine(_root, ".build", "gt-cli", "gt-cli");
            Assert.That(File.Exists(_cli), Is.True, "gt-cli not built at " + _cli + " (run Tools~/gt setup)");
            _work = Path.Combine(_root, ".build", "rigtests-terrain");
            if (Directory.Exists(_work)) Directory.Delete(_work, true);
            Directory.CreateDirectory(_work);
            _gridPath = Path.Combine(_work, "grid.json");
            Exec(_cli, new[] { "demo-grid", "--samples", "129", "--out", _gridPath }, null);
            _grid = PatchGridJson.Read(File.ReadAllText(_gridPath));
            Exec("bash", new[] { Path.Combine(_root, "Tools~", "gt"), "shaders", "--only", "readback", "--only", "readback+noise", "--only", "noise+height_color" },
                 new Dictionary<string, string> { ["GT_BUILD_DIR"] = _work });
            _spirv = Path.Combine(_work, "spirv");
        }

        static string Exec(string file, string[] args, Dictionary<string, string> env)
        {
            var psi = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) psi.ArgumentList.Add(a);
            if (env != null) foreach (var kv in env) psi.Environment[kv.Key] = kv.Value;
            using (var p = Process.Start(psi))
            {
                var err = p.StandardError.ReadToEndAsync();
                string output = p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                Assert.That(p.ExitCode, Is.EqualTo(0), file + " " + string.Join(" ", args) + " failed:\n" + output + err.Result);
                return output;
            }
        }

        // ---- readback runs ----------------------------------------------------------------------

        static void WriteFloats(string path, float[] values)
        {
            var bytes = new byte[values.Length * 4];
            Buffer.BlockCopy(values, 0, bytes, 0, bytes.Length);   // little-endian on every .NET the rig runs
            File.WriteAllBytes(path, bytes);
        }

        static float[] ReadFloats(string path)
        {
            byte[] b = File.ReadAllBytes(path);
            var f = new float[b.Length / 4];
            Buffer.BlockCopy(b, 0, f, 0, f.Length * 4);
            return f;
        }

        /// <summary>Draws the grid at <paramref name="range"/> with M x M tiles at uniform factor F and reads every vertex back.</summary>
        Run Readback(string name, TerrainRange range, bool noise)
        {
            string key = name + (noise ? "+noise" : "");
            if (_runs.TryGetValue(key, out Run cached)) return cached;
            var p = TerrainParams.Create(_grid, range, RangeOrigin.For(range), TessellationSettings.Uniform(Tiles, Factor),
                Noise, Colors, new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f));
            var inputs = TerrainInputs.Create(_grid, p);
            string dir = Path.Combine(_work, key);
            Directory.CreateDirectory(dir);
            WriteFloats(Path.Combine(dir, "control_points.f32"), inputs.ControlPoints);
            WriteFloats(Path.Combine(dir, "regions.f32"), inputs.Regions);
            WriteFloats(Path.Combine(dir, "grid_lines.f32"), inputs.GridLines);
            WriteFloats(Path.Combine(dir, "params.f32"), p.Pack());
            // A top-down orthographic camera over the unit square (object (x, z) -> clip); the
            // readback does not depend on it.
            float[,] m = { { 2, 0, 0, -1 }, { 0, 0, 2, -1 }, { 0, 0.01f, 0, 0.5f }, { 0, 0, 0, 1 } };
            var cam = new List<float>();
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(m[r, c]);
            for (int c = 0; c < 4; c++) for (int r = 0; r < 4; r++) cam.Add(r == c ? 1 : 0);
            cam.AddRange(new float[] { 0.5f, 2, 0.5f, 1, 64, 64, 1f / 64, 1f / 64, 0, 1, 0, 0 });
            WriteFloats(Path.Combine(dir, "camera.f32"), cam.ToArray());
            string variant = Path.Combine(_spirv, noise ? "readback+noise" : "readback");
            string readback = Path.Combine(dir, "readback.f32");
            HarnessRun h = HarnessRun.Harness(
                "--vert", Path.Combine(variant, "vert.spv"), "--tesc", Path.Combine(variant, "tesc.spv"),
                "--tese", Path.Combine(variant, "tese.spv"), "--frag", Path.Combine(variant, "frag.spv"),
                "--buffers", dir, "--patches", (Tiles * Tiles).ToString(), "--width", "64", "--height", "64",
                "--device", "llvmpipe", "--stats", "--readback", readback, "--readback-floats", (12 * VerticesPerRun).ToString());
            h.AssertSucceeded();
            Assert.That(h.Value("readback", readback), Is.Not.Null, "no readback line:\n" + h.Stdout);
            var run = new Run { Name = key, Inputs = inputs, Keywords = noise ? TerrainKeywords.Noise : TerrainKeywords.None,
                                Readback = ReadFloats(readback), Harness = h };
            Assert.That(run.Readback.Length, Is.EqualTo(12 * VerticesPerRun));
            _runs[key] = run;
            return run;
        }

        // ---- GPU vs Core ------------------------------------------------------------------------

        /// <summary>
        /// The tess coordinate lavapipe used on one axis. Its tessellator works in 16.16 fixed point,
        /// so s is a multiple of 2^-16 near index/F (26/63 reads 0.41259765625): the candidate whose
        /// q and u, through Core's float RangeToTerrainPoint and PatchLocalUV, are the GPU's bit for
        /// bit. NaN when none is.
        /// </summary>
        static float GpuTessCoordinate(TerrainInputs inputs, bool xAxis, int tile, int index, float gpuQ, float gpuLocal, Float4 region)
        {
            double nominal = (double)index / Factor;
            int centre = (int)Math.Round(nominal * 65536);
            for (int k = 0; k <= 64; k++)
                foreach (int sign in k == 0 ? new[] { 1 } : new[] { 1, -1 })
                {
                    int fx = centre + sign * k;
                    if (fx < 0 || fx > 65536) continue;
                    float s = fx / 65536f;
                    TerrainPoint q = xAxis
                        ? RangeMapping.ToTerrainPoint(inputs.Params.range, inputs.Params.rangeOrigin, Tiles, tile, 0, s, 0f)
                        : RangeMapping.ToTerrainPoint(inputs.Params.range, inputs.Params.rangeOrigin, Tiles, 0, tile, 0f, s);
                    Float2 approx = RangeMapping.Approximate(q);
                    Float2 uv = RangeMapping.PatchLocalUV(q, region);
                    if (xAxis ? approx.x == gpuQ && uv.x == gpuLocal : approx.y == gpuQ && uv.y == gpuLocal) return s;
                }
            return float.NaN;
        }

        sealed class Comparison
        {
            public int Vertices, Unmatched, PositionBitIdentical, NormalBitIdentical, QEqual, Nan;
            public double MaxPosition, MaxNormal, MaxReference;
            public HashSet<int> Patches = new HashSet<int>();
        }

        /// <summary>Core's float path at the GPU's tess coordinates, vertex by vertex, against the readback.</summary>
        Comparison Compare(Run run, double extent)
        {
            var c = new Comparison();
            float[] v = run.Readback;
            int per = (Factor + 1) * (Factor + 1);
            var sCache = new Dictionary<(bool, int, int, float, float), float>();
            for (int k = 0; k < VerticesPerRun; k++)
            {
                int o = 12 * k;
                if (Enumerable.Range(o, 12).Any(i => float.IsNaN(v[i]))) { c.Nan++; continue; }
                int tile = k / per, row = k % per / (Factor + 1), col = k % (Factor + 1);
                int ti = tile % Tiles, tj = tile / Tiles;
                var gpuQ = new Float2(v[o + 8], v[o + 9]);
                int patch = run.Inputs.FindPatch(gpuQ);
                Float4 region = run.Inputs.PatchRegion(patch);
                float s = Cached(sCache, (true, ti, col, gpuQ.x, v[o + 10]), () => GpuTessCoordinate(run.Inputs, true, ti, col, gpuQ.x, v[o + 10], region));
                float t = Cached(sCache, (false, tj, row, gpuQ.y, v[o + 11]), () => GpuTessCoordinate(run.Inputs, false, tj, row, gpuQ.y, v[o + 11], region));
                if (float.IsNaN(s) || float.IsNaN(t))
                {
                    c.Unmatched++;
                    s = float.IsNaN(s) ? (float)col / Factor : s;
                    t = float.IsNaN(t) ? (float)row / Factor : t;
                }
                TerrainVertexOutput core = TerrainVertex.Evaluate(run.Inputs, tile, new Float2(s, t), run.Keywords);
                Float3 gp = new Float3(v[o], v[o + 1], v[o + 2]), gn = new Float3(v[o + 4], v[o + 5], v[o + 6]);
                Float3 cp = core.PositionOS, cn = core.NormalOS;
                c.Vertices++;
                c.Patches.Add(core.surface.patch);
                if (gp.Equals(cp)) c.PositionBitIdentical++;
                if (gn.Equals(cn)) c.NormalBitIdentical++;
                if (RangeMapping.Approximate(core.surface.q).Equals(gpuQ)) c.QEqual++;
                c.MaxPosition = Math.Max(c.MaxPosition, Distance(gp, cp) / extent);
                c.MaxNormal = Math.Max(c.MaxNormal, Distance(gn, cn));
                // And the float path against the double reference at the same exact point.
                TerrainVertex.Reference(_grid, core.surface.q.ToDouble(),
                    (run.Keywords & TerrainKeywords.Noise) != 0 ? Noise : (NoiseSettings?)null, run.Inputs.NoiseOctaveCount(),
                    out Double3 rp, out _);
                rp -= TerrainVertex.OutputOffset(_grid, run.Inputs.Params.rangeOrigin, run.Keywords);
                c.MaxReference = Math.Max(c.MaxReference, GMath.length(new Double3(core.position.x, core.position.y, core.position.z) - rp) / extent);
            }
            return c;
        }

        static float Cached(Dictionary<(bool, int, int, float, float), float> cache, (bool, int, int, float, float) key, Func<float> f)
        {
            if (!cache.TryGetValue(key, out float s)) cache[key] = s = f();
            return s;
        }

        static double Distance(Float3 a, Float3 b)
        {
            double dx = (double)a.x - b.x, dy = (double)a.y - b.y, dz = (double)a.z - b.z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        /// <summary>The diagonal of the control points' bounding box: the terrain's extent.</summary>
        double TerrainExtent()
        {
            var lo = new Double3(double.MaxValue, double.MaxValue, double.MaxValue);
            var hi = new Double3(double.MinValue, double.MinValue, double.MinValue);
            foreach (GregoryPatch p in _grid.Patches)
                foreach (Double3 q in p.Points)
                {
                    lo = new Double3(Math.Min(lo.x, q.x), Math.Min(lo.y, q.y), Math.Min(lo.z, q.z));
                    hi = new Double3(Math.Max(hi.x, q.x), Math.Max(hi.y, q.y), Math.Max(hi.z, q.z));
                }
            return GMath.length(hi - lo);
        }

        [Test]
        public void GpuReadbackMatchesCoreFloatPathOnEveryPatchAtSeveralRanges()
        {
            double extent = TerrainExtent();
            int total = 0, unmatched = 0, bitPos = 0, bitNormal = 0, qEqual = 0, nan = 0;
            double maxPos = 0, maxNormal = 0, maxRef = 0;
            foreach (bool noise in new[] { false, true })
            {
                int totalThis = 0;
                foreach (var (name, range) in Ranges)
                {
                    Comparison c = Compare(Readback(name, range, noise), extent);
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
                    float[] v = Readback(name, range, noise).Readback;
                    int per = (Factor + 1) * (Factor + 1);
                    int Index(int ti, int tj, int row, int col) => (tj * Tiles + ti) * per + row * (Factor + 1) + col;
                    for (int tj = 0; tj < Tiles; tj++)
                        for (int ti = 0; ti < Tiles; ti++)
                            for (int i = 0; i <= Factor; i++)
                            {
                                if (ti + 1 < Tiles)   // right edge of (ti, tj) = left edge of (ti + 1, tj)
                                {
                                    pairs++;
                                    if (!SameBits(v, Index(ti, tj, i, Factor), Index(ti + 1, tj, i, 0))) differing++;
                                }
                                if (tj + 1 < Tiles)   // top edge of (ti, tj) = bottom edge of (ti, tj + 1)
                                {
                                    pairs++;
                                    if (!SameBits(v, Index(ti, tj, Factor, i), Index(ti, tj + 1, 0, i))) differing++;
                                }
                            }
                }
            TestContext.Out.WriteLine("shared tile edges: {0} vertex pairs, {1} differ in any bit of position, normal, q or u, v", pairs, differing);
            // Per run: M (M - 1) shared edges each way, F + 1 vertices on each.
            Assert.That(pairs, Is.EqualTo(2 * Ranges.Length * 2 * Tiles * (Tiles - 1) * (Factor + 1)));
            Assert.That(differing, Is.EqualTo(0));
        }

        static bool SameBits(float[] v, int a, int b)
        {
            for (int k = 0; k < 12; k++)
                if (k % 4 != 3 && BitConverter.SingleToInt32Bits(v[12 * a + k]) != BitConverter.SingleToInt32Bits(v[12 * b + k])) return false;
            return true;
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
            Exec(_cli, new[] { "pack", "--grid", _gridPath, "--range", r, "--tiles", "8", "--width", "160", "--height", "120", "--out", dir }, null);
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

        /// <summary>RGB bytes of a harness PNG (RGBA, filter None per row).</summary>
        static byte[] DecodeRgb(string path, int width, int height)
        {
            byte[] png = File.ReadAllBytes(path);
            var idat = new MemoryStream();
            for (int i = 8; i < png.Length;)
            {
                int len = png[i] << 24 | png[i + 1] << 16 | png[i + 2] << 8 | png[i + 3];
                string type = System.Text.Encoding.ASCII.GetString(png, i + 4, 4);
                if (type == "IHDR")
                {
                    Assert.That(png[i + 8] << 24 | png[i + 9] << 16 | png[i + 10] << 8 | png[i + 11], Is.EqualTo(width));
                    Assert.That(png[i + 12] << 24 | png[i + 13] << 16 | png[i + 14] << 8 | png[i + 15], Is.EqualTo(height));
                }
                if (type == "IDAT") idat.Write(png, i + 8, len);
                i += 12 + len;
            }
            byte[] raw;
            using (var inflate = new ZLibStream(new MemoryStream(idat.ToArray()), CompressionMode.Decompress))
            using (var o = new MemoryStream())
            {
                inflate.CopyTo(o);
                raw = o.ToArray();
            }
            Assert.That(raw.Length, Is.EqualTo(height * (1 + 4 * width)));
            var rgb = new byte[3 * width * height];
            for (int y = 0; y < height; y++)
            {
                Assert.That(raw[y * (1 + 4 * width)], Is.EqualTo(0), "filter byte");
                for (int x = 0; x < width; x++)
                    for (int c = 0; c < 3; c++)
                        rgb[3 * (y * width + x) + c] = raw[y * (1 + 4 * width) + 1 + 4 * x + c];
            }
            return rgb;
        }
    }
}
