using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Samples~/TerrainFlyover/PatchGrid.asset (and its copy in Samples~/GroundWalk) must be the real fitted grid: its YAML is read back
    /// (numbers parsed here, not by the tool that wrote them) into a PatchGrid that is valid and equal,
    /// bit for bit, to what <c>gt-cli demo-grid</c> builds; its fields must be PatchGridAsset's
    /// serialized fields in declaration order; and <c>gt-cli unity-asset</c> must reproduce the file.
    /// </summary>
    [TestFixture]
    public class SampleGridAssetTests
    {
        /// <summary>The grid of each sample that ships one (a sample is imported on its own, so each has its copy).</summary>
        static string AssetPath(string sample) => PackageRoot.Combine("Samples~", sample, "PatchGrid.asset");
        string _tmp;
        PatchGrid _demo;
        string _demoJsonPath;

        [OneTimeSetUp]
        public void BuildDemoGrid()
        {
            _tmp = Path.Combine(Path.GetTempPath(), "gt-sample-grid-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_tmp);
            _demoJsonPath = Path.Combine(_tmp, "demo.json");
            RunGtCli("demo-grid", "--out", _demoJsonPath);
            _demo = PatchGridJson.Read(File.ReadAllText(_demoJsonPath));
        }

        [OneTimeTearDown]
        public void Clean()
        {
            if (_tmp != null && Directory.Exists(_tmp)) Directory.Delete(_tmp, true);
        }

        [TestCase("TerrainFlyover")]
        [TestCase("GroundWalk")]
        public void AssetParsesIntoAValidGridEqualToTheDemoGrid(string sample)
        {
            PatchGrid asset = ReadAsset(File.ReadAllText(AssetPath(sample)));
            Assert.DoesNotThrow(asset.Validate);
            Assert.That(asset.Columns, Is.EqualTo(_demo.Columns));
            Assert.That(asset.Rows, Is.EqualTo(_demo.Rows));
            Assert.That(asset.XLines, Is.EqualTo(_demo.XLines));
            Assert.That(asset.YLines, Is.EqualTo(_demo.YLines));
            int differing = 0;
            double zMin = double.MaxValue, zMax = double.MinValue;
            for (int p = 0; p < asset.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    Double3 a = asset.Patches[p][k], d = _demo.Patches[p][k];
                    // Bit-for-bit: the YAML numbers are round-trip decimals.
                    if (BitConverter.DoubleToInt64Bits(a.x) != BitConverter.DoubleToInt64Bits(d.x) ||
                        BitConverter.DoubleToInt64Bits(a.y) != BitConverter.DoubleToInt64Bits(d.y) ||
                        BitConverter.DoubleToInt64Bits(a.z) != BitConverter.DoubleToInt64Bits(d.z)) differing++;
                    zMin = Math.Min(zMin, a.z); zMax = Math.Max(zMax, a.z);
                }
            Assert.That(differing, Is.EqualTo(0), "control points that differ from gt-cli demo-grid");
            double g1 = ContinuityMeasure.MaxNormalAngleDegrees(asset);
            TestContext.Out.WriteLine(FormattableString.Invariant(
                $"sample asset: {asset.Columns}x{asset.Rows} patches, control point z in [{zMin:G4}, {zMax:G4}], max normal angle across shared edges {g1:G3} deg"));
            Assert.That(zMax - zMin, Is.GreaterThan(0.01), "not a flat placeholder");
            Assert.That(g1, Is.LessThan(1e-6), "the fitted grid is G1");
        }

        [TestCase("TerrainFlyover")]
        [TestCase("GroundWalk")]
        public void AssetFieldsAreThePatchGridAssetSerializedFieldsInOrder(string sample)
        {
            string source = File.ReadAllText(PackageRoot.Combine("Runtime", "PatchGridAsset.cs"));
            var declared = Regex.Matches(source, @"\[SerializeField[^\]]*\]\s*(?:\w+(?:\[\])?)\s+(\w+)\s*=")
                .Select(m => m.Groups[1].Value).ToList();
            Assert.That(declared, Is.EqualTo(new[] { "columns", "rows", "xLines", "yLines", "blocks", "controlPoints" }), "PatchGridAsset's serialized fields");
            string yaml = File.ReadAllText(AssetPath(sample));
            var written = Regex.Matches(yaml, @"^  (\w+):", RegexOptions.Multiline).Select(m => m.Groups[1].Value)
                .Where(n => !n.StartsWith("m_")).ToList();
            Assert.That(written, Is.EqualTo(declared));

            string meta = File.ReadAllText(PackageRoot.Combine("Runtime", "PatchGridAsset.cs.meta"));
            string guid = Regex.Match(meta, @"^guid: ([0-9a-f]{32})", RegexOptions.Multiline).Groups[1].Value;
            Assert.That(yaml, Does.Contain($"m_Script: {{fileID: 11500000, guid: {guid}, type: 3}}"));
        }

        [TestCase("TerrainFlyover")]
        [TestCase("GroundWalk")]
        public void UnityAssetCommandReproducesTheSampleFile(string sample)
        {
            string meta = File.ReadAllText(PackageRoot.Combine("Runtime", "PatchGridAsset.cs.meta"));
            string guid = Regex.Match(meta, @"^guid: ([0-9a-f]{32})", RegexOptions.Multiline).Groups[1].Value;
            string output = Path.Combine(_tmp, "PatchGrid.asset");
            RunGtCli("unity-asset", "--grid", _demoJsonPath, "--out", output, "--script-guid", guid, "--name", "PatchGrid");
            Assert.That(File.ReadAllText(output), Is.EqualTo(File.ReadAllText(AssetPath(sample))),
                "regenerate with: gt-cli demo-grid --out g.json; gt-cli unity-asset --grid g.json --out Samples~/" + sample + "/PatchGrid.asset --script-guid " + guid);
        }

        /// <summary>
        /// The fit's sums do not depend on the SIMD width (GregoryLeastSquares: fixed order, lanes
        /// only as independent entries), so a machine with 2-wide vectors (Mono's, SSE) or none
        /// writes the same grid as this one's, to the bit. Run with AVX off (2 doubles a vector) and
        /// with hardware intrinsics off. (Before the fixed-order sums, AVX and SSE grids differed.)
        /// </summary>
        [TestCase("DOTNET_EnableAVX")]
        [TestCase("DOTNET_EnableHWIntrinsic")]
        public void DemoGridIsTheSameAtAnySimdWidth(string switchOff)
        {
            string path = Path.Combine(_tmp, switchOff + ".json");
            var (code, output) = TryGtCliWith(new[] { (switchOff, "0") }, "demo-grid", "--out", path);
            Assert.That(code, Is.EqualTo(0), output);
            PatchGrid other = PatchGridJson.Read(File.ReadAllText(path));
            int differing = 0;
            for (int p = 0; p < other.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                    if (BitConverter.DoubleToInt64Bits(other.Patches[p][k].z) != BitConverter.DoubleToInt64Bits(_demo.Patches[p][k].z)) differing++;
            Assert.That(differing, Is.EqualTo(0), $"control points that differ with {switchOff}=0");
        }

        [Test]
        public void UnityAssetCommandRejectsABadGuid()
        {
            var (code, output) = TryGtCli("unity-asset", "--grid", _demoJsonPath, "--out", Path.Combine(_tmp, "x.asset"), "--script-guid", "XYZ");
            Assert.That(code, Is.Not.EqualTo(0));
            Assert.That(output, Does.Contain("--script-guid 'XYZ'"));
            Assert.That(File.Exists(Path.Combine(_tmp, "x.asset")), Is.False);
        }

        /// <summary>
        /// Reads the PatchGridAsset YAML: "  columns: N", "  rows: M" and the three sequences of
        /// doubles, into Core's PatchGrid (20 (x, y, z) per patch, slot order, patch j * n + i).
        /// </summary>
        static PatchGrid ReadAsset(string yaml)
        {
            int columns = int.Parse(Regex.Match(yaml, @"^  columns: (\d+)$", RegexOptions.Multiline).Groups[1].Value, CultureInfo.InvariantCulture);
            int rows = int.Parse(Regex.Match(yaml, @"^  rows: (\d+)$", RegexOptions.Multiline).Groups[1].Value, CultureInfo.InvariantCulture);
            double[] xs = Sequence(yaml, "xLines"), ys = Sequence(yaml, "yLines"), cps = Sequence(yaml, "controlPoints");
            Assert.That(cps.Length, Is.EqualTo(columns * rows * 3 * GregoryPatch.SlotCount), "controlPoints length");
            var patches = new GregoryPatch[columns * rows];
            for (int p = 0; p < patches.Length; p++)
            {
                patches[p] = new GregoryPatch();
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    int o = (p * GregoryPatch.SlotCount + k) * 3;
                    patches[p][k] = new Double3(cps[o], cps[o + 1], cps[o + 2]);
                }
            }
            return new PatchGrid(columns, rows, xs, ys, patches);
        }

        static double[] Sequence(string yaml, string field)
        {
            var lines = yaml.Replace("\r\n", "\n").Split('\n');
            int start = Array.IndexOf(lines, $"  {field}:");
            Assert.That(start, Is.GreaterThanOrEqualTo(0), field + " not found");
            var values = new List<double>();
            for (int i = start + 1; i < lines.Length && lines[i].StartsWith("  - ", StringComparison.Ordinal); i++)
                values.Add(double.Parse(lines[i].Substring(4), NumberStyles.Float, CultureInfo.InvariantCulture));
            return values.ToArray();
        }

        static void RunGtCli(params string[] args)
        {
            var (code, output) = TryGtCli(args);
            Assert.That(code, Is.EqualTo(0), $"gt-cli {string.Join(" ", args)}:\n{output}");
        }

        /// <summary>gt-cli as `gt setup` builds it (into $GT_BUILD_DIR/gt-cli), else through dotnet run.</summary>
        static (int, string) TryGtCli(params string[] args) => TryGtCliWith(null, args);

        static (int, string) TryGtCliWith((string name, string value)[] env, params string[] args)
        {
            string buildDir = Environment.GetEnvironmentVariable("GT_BUILD_DIR") ?? PackageRoot.Combine(".build");
            string dll = Path.Combine(buildDir, "gt-cli", "gt-cli.dll");
            var psi = File.Exists(dll)
                ? new ProcessStartInfo("dotnet") { ArgumentList = { dll } }
                : new ProcessStartInfo("dotnet") { ArgumentList = { "run", "--project", PackageRoot.Combine("Tools~", "dotnet", "Gt"), "-c", "Release", "--" } };
            foreach (string a in args) psi.ArgumentList.Add(a);
            psi.RedirectStandardOutput = true;
            psi.RedirectStandardError = true;
            psi.UseShellExecute = false;
            if (env != null) foreach (var (name, value) in env) psi.Environment[name] = value;
            using var p = Process.Start(psi);
            string output = p.StandardOutput.ReadToEnd() + p.StandardError.ReadToEnd();
            p.WaitForExit();
            return (p.ExitCode, output);
        }
    }
}
