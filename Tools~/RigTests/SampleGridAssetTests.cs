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
    /// bit for bit, to what <c>gt-cli demo-grid</c> builds; it must be saved in the current layout
    /// (block sub-assets, each bit for bit Core's PatchGridBlocks of that grid; no single array, so the
    /// asset inspector shows no "move to blocks" notice); its fields must be PatchGridAsset's and
    /// PatchGridBlock's serialized fields in declaration order; and <c>gt-cli unity-asset</c> must
    /// reproduce the file.
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
            var declared = DeclaredFields("PatchGridAsset.cs");
            Assert.That(declared, Is.EqualTo(new[] { "columns", "rows", "xLines", "yLines", "blocks", "controlPoints" }), "PatchGridAsset's serialized fields");
            var blockDeclared = DeclaredFields("PatchGridBlock.cs");
            Assert.That(blockDeclared, Is.EqualTo(new[] { "owner", "points" }), "PatchGridBlock's serialized fields");
            var documents = Documents(File.ReadAllText(AssetPath(sample)));
            Assert.That(documents[0].fileId, Is.EqualTo(11400000L), "the grid is the file's first object");
            Assert.That(Keys(documents[0].text), Is.EqualTo(declared));
            Assert.That(documents[0].text, Does.Contain($"m_Script: {{fileID: 11500000, guid: {ScriptGuid("PatchGridAsset.cs")}, type: 3}}"));
            foreach (var (fileId, text) in documents.Skip(1))
            {
                Assert.That(Keys(text), Is.EqualTo(blockDeclared), "block " + fileId);
                Assert.That(text, Does.Contain($"m_Script: {{fileID: 11500000, guid: {ScriptGuid("PatchGridBlock.cs")}, type: 3}}"), "block " + fileId);
                Assert.That(text, Does.Contain("  m_ObjectHideFlags: 1\n"), "block " + fileId + " is hidden in the hierarchy, as PatchGridBlock.Create makes it");
            }
        }

        /// <summary>
        /// The current layout: every control point in block sub-assets, none left in the single array
        /// (the asset inspector's "move to blocks" notice), and each block's doubles, in order, bit for
        /// bit the block Core's PatchGridBlocks.FromGrid cuts from the demo grid.
        /// </summary>
        [TestCase("TerrainFlyover")]
        [TestCase("GroundWalk")]
        public void AssetIsSavedInBlocksEqualToCoresBlocks(string sample)
        {
            string yaml = File.ReadAllText(AssetPath(sample));
            var documents = Documents(yaml);
            Assert.That(Sequence(documents[0].text, "controlPoints").Length, Is.EqualTo(0), "doubles left in controlPoints (the single-array layout)");
            Assert.That(documents[0].text, Does.Contain("  controlPoints: []\n"));
            long[] refs = BlockReferences(documents[0].text);
            double[][] core = PatchGridBlocks.FromGrid(_demo);
            Assert.That(refs.Length, Is.EqualTo(core.Length), "blocks");
            for (int b = 0; b < core.Length; b++)
            {
                var doc = documents.Single(d => d.fileId == refs[b]);
                Assert.That(doc.text, Does.Contain("  owner: {fileID: 11400000}\n"), "block " + b + "'s owner");
                Assert.That(doc.text, Does.Contain("  m_Name: Block " + b + "\n"), "block " + b + "'s name");
                double[] points = Sequence(doc.text, "points");
                Assert.That(points.Length, Is.EqualTo(core[b].Length), "block " + b + " length");
                int differing = Enumerable.Range(0, points.Length)
                    .Count(i => BitConverter.DoubleToInt64Bits(points[i]) != BitConverter.DoubleToInt64Bits(core[b][i]));
                Assert.That(differing, Is.EqualTo(0), "doubles of block " + b + " that differ from Core's");
            }
            Assert.That(documents.Count, Is.EqualTo(1 + core.Length), "objects in the file: the grid and its blocks");
        }

        static List<string> DeclaredFields(string script) =>
            Regex.Matches(File.ReadAllText(PackageRoot.Combine("Runtime", script)), @"\[SerializeField[^\]]*\]\s*(?:\w+(?:\[\])?)\s+(\w+)\s*[=;]")
                .Select(m => m.Groups[1].Value).ToList();

        static List<string> Keys(string document) =>
            Regex.Matches(document, @"^  (\w+):", RegexOptions.Multiline).Select(m => m.Groups[1].Value).Where(n => !n.StartsWith("m_")).ToList();

        static string ScriptGuid(string script) =>
            Regex.Match(File.ReadAllText(PackageRoot.Combine("Runtime", script + ".meta")), @"^guid: ([0-9a-f]{32})", RegexOptions.Multiline).Groups[1].Value;

        [TestCase("TerrainFlyover")]
        [TestCase("GroundWalk")]
        public void UnityAssetCommandReproducesTheSampleFile(string sample)
        {
            string guid = ScriptGuid("PatchGridAsset.cs"), blockGuid = ScriptGuid("PatchGridBlock.cs");
            string output = Path.Combine(_tmp, "PatchGrid.asset");
            RunGtCli("unity-asset", "--grid", _demoJsonPath, "--out", output, "--script-guid", guid, "--block-script-guid", blockGuid, "--name", "PatchGrid");
            Assert.That(File.ReadAllText(output), Is.EqualTo(File.ReadAllText(AssetPath(sample))),
                "regenerate with: gt-cli demo-grid --out g.json; gt-cli unity-asset --grid g.json --out Samples~/" + sample + "/PatchGrid.asset --script-guid " + guid + " --block-script-guid " + blockGuid);
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
            var (code, output) = TryGtCli("unity-asset", "--grid", _demoJsonPath, "--out", Path.Combine(_tmp, "x.asset"), "--script-guid", "XYZ", "--block-script-guid", ScriptGuid("PatchGridBlock.cs"));
            Assert.That(code, Is.Not.EqualTo(0));
            Assert.That(output, Does.Contain("--script-guid 'XYZ'"));
            Assert.That(File.Exists(Path.Combine(_tmp, "x.asset")), Is.False);
        }

        [Test]
        public void UnityAssetCommandRejectsTheGridsGuidAsTheBlocks()
        {
            string guid = ScriptGuid("PatchGridAsset.cs");
            var (code, output) = TryGtCli("unity-asset", "--grid", _demoJsonPath, "--out", Path.Combine(_tmp, "y.asset"), "--script-guid", guid, "--block-script-guid", guid);
            Assert.That(code, Is.Not.EqualTo(0));
            Assert.That(output, Does.Contain($"--block-script-guid '{guid}'"));
            Assert.That(File.Exists(Path.Combine(_tmp, "y.asset")), Is.False);
        }

        /// <summary>
        /// Reads the PatchGridAsset YAML: "  columns: N", "  rows: M", the grid lines and the control
        /// points (the blocks' "points" in the order the grid lists them, or the older single array),
        /// into Core's PatchGrid (20 (x, y, z) per patch, slot order, patch j * n + i).
        /// </summary>
        internal static PatchGrid ReadAsset(string yaml)
        {
            var documents = Documents(yaml);
            string grid = documents[0].text;
            int columns = int.Parse(Regex.Match(grid, @"^  columns: (\d+)$", RegexOptions.Multiline).Groups[1].Value, CultureInfo.InvariantCulture);
            int rows = int.Parse(Regex.Match(grid, @"^  rows: (\d+)$", RegexOptions.Multiline).Groups[1].Value, CultureInfo.InvariantCulture);
            double[] xs = Sequence(grid, "xLines"), ys = Sequence(grid, "yLines");
            double[] cps = Sequence(grid, "controlPoints");
            if (cps.Length == 0)
                cps = BlockReferences(grid).SelectMany(id => Sequence(documents.Single(d => d.fileId == id).text, "points")).ToArray();
            Assert.That(cps.Length, Is.EqualTo(columns * rows * 3 * GregoryPatch.SlotCount), "control points");
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

        /// <summary>The file's objects, in order: (file ID, text from its "--- !u!" line to the next).</summary>
        internal static List<(long fileId, string text)> Documents(string yaml)
        {
            yaml = yaml.Replace("\r\n", "\n");
            var heads = Regex.Matches(yaml, @"^--- !u!114 &(-?\d+)\n", RegexOptions.Multiline).ToList();
            Assert.That(heads.Count, Is.GreaterThan(0), "no MonoBehaviour object in the asset");
            return heads.Select((m, k) => (long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture),
                                           yaml.Substring(m.Index, (k + 1 < heads.Count ? heads[k + 1].Index : yaml.Length) - m.Index))).ToList();
        }

        /// <summary>The file IDs the grid's "blocks" list references, in order.</summary>
        static long[] BlockReferences(string grid)
        {
            var lines = grid.Split('\n');
            int start = Array.IndexOf(lines, "  blocks:");
            if (start < 0) return Array.Empty<long>();
            var ids = new List<long>();
            for (int i = start + 1; i < lines.Length && lines[i].StartsWith("  - ", StringComparison.Ordinal); i++)
                ids.Add(long.Parse(Regex.Match(lines[i], @"^  - \{fileID: (-?\d+)\}$").Groups[1].Value, CultureInfo.InvariantCulture));
            return ids.ToArray();
        }

        static double[] Sequence(string yaml, string field)
        {
            var lines = yaml.Replace("\r\n", "\n").Split('\n');
            if (Array.IndexOf(lines, $"  {field}: []") >= 0) return Array.Empty<double>();
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
