using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The rig's own keywords, in one place: Tools~/rig/TerrainRig.hlsl turns each into one of the
    /// product's neutral extension points (internals.md, "Extension points"); no file the package
    /// ships may name them.
    /// </summary>
    static class RigKeywords
    {
        /// <summary>Paper mode, the vertex and factor readbacks, and gt bench's fair static mesh.</summary>
        public static readonly string[] RigOnly = { "GT_PAPER_MODE", "GT_READBACK", "GT_FACTOR_READBACK", "GT_STATIC_MESH" };

        /// <summary>The product's extension points: only tested (#if defined), never defined, under Shaders/.</summary>
        public const string ExtensionPrefix = "GT_EXTEND_";

        /// <summary>The rig's entry file.</summary>
        public static string EntryFile => PackageRoot.Combine("Tools~", "rig", "TerrainRig.hlsl");

        /// <summary>"file:line: text" of each line of the files under <paramref name="shadersDir"/> that names a rig-only keyword.</summary>
        public static string[] Mentions(string shadersDir) =>
            Directory.GetFiles(shadersDir, "*", SearchOption.AllDirectories)
                .Where(f => !f.EndsWith(".meta"))
                .SelectMany(f => File.ReadAllLines(f).Select((line, i) => (f, line, i)))
                .Where(x => RigOnly.Any(k => Regex.IsMatch(x.line, @"\b" + k + @"\b")))
                .Select(x => $"{Path.GetRelativePath(shadersDir, x.f)}:{x.i + 1}: {x.line.Trim()}")
                .ToArray();

        /// <summary>"file:line: text" of each line under <paramref name="shadersDir"/> that defines or declares an extension point.</summary>
        public static string[] ExtensionDefinitions(string shadersDir) =>
            Directory.GetFiles(shadersDir, "*", SearchOption.AllDirectories)
                .Where(f => !f.EndsWith(".meta"))
                .SelectMany(f => File.ReadAllLines(f).Select((line, i) => (f, line, i)))
                .Where(x => Regex.IsMatch(x.line, @"^\s*#\s*(define|pragma\b.*)\s+.*\b" + ExtensionPrefix + @"\w*"))
                .Select(x => $"{Path.GetRelativePath(shadersDir, x.f)}:{x.i + 1}: {x.line.Trim()}")
                .ToArray();
    }

    /// <summary>The product's shaders carry no rig branches; the rig reaches them through its entry file.</summary>
    [TestFixture]
    public class RigKeywordTests
    {
        [Test]
        public void NoFileUnderShadersNamesARigOnlyKeyword()
        {
            string[] found = RigKeywords.Mentions(PackageRoot.Combine("Shaders"));
            Assert.That(found, Is.Empty, "rig-only keywords under Shaders/:\n" + string.Join("\n", found));
        }

        [Test]
        public void NoFileUnderShadersTurnsOnAnExtensionPoint()
        {
            string[] found = RigKeywords.ExtensionDefinitions(PackageRoot.Combine("Shaders"));
            Assert.That(found, Is.Empty, "extension points defined under Shaders/:\n" + string.Join("\n", found));
        }

        // The list is the rig's: each keyword is tested by the entry file (a stale entry would make the
        // check above weaker without anyone noticing), and the entry file tests no other GT_ keyword
        // of its own.
        [Test]
        public void TheListIsExactlyTheKeywordsTheRigEntryFileTests()
        {
            string text = File.ReadAllText(RigKeywords.EntryFile);
            var tested = Regex.Matches(text, @"defined\((GT_\w+)\)").Select(m => m.Groups[1].Value)
                .Where(k => !k.StartsWith(RigKeywords.ExtensionPrefix)).Distinct().ToList();
            // The product's own keywords the entry file checks against (the cache's and the levels' kernels
            // have no rig modes).
            tested.Remove("GT_VERTEX_CACHE");
            tested.Remove("GT_LOD");
            tested.Remove("GT_TERRAIN_RIG_INCLUDED");
            Assert.That(tested, Is.EquivalentTo(RigKeywords.RigOnly));
        }

        // The check itself finds a mention: a copy of Shaders/ with one rig branch put back.
        [Test]
        public void TheCheckFindsARigBranchInACopyOfShaders()
        {
            string copy = Path.Combine(Path.GetTempPath(), "gt-rigkeywords-" + System.Guid.NewGuid().ToString("N"));
            try
            {
                string stages = Path.Combine(copy, "Pipelines", "TerrainStages.hlsl");
                Directory.CreateDirectory(Path.GetDirectoryName(stages));
                File.WriteAllText(stages, File.ReadAllText(PackageRoot.Combine("Shaders", "Pipelines", "TerrainStages.hlsl"))
                    + "\n#if defined(GT_READBACK)\n#endif\n#define GT_EXTEND_VERTEX\n");
                Assert.That(RigKeywords.Mentions(copy), Has.Length.EqualTo(1).And.Some.Contains("GT_READBACK"));
                Assert.That(RigKeywords.ExtensionDefinitions(copy), Has.Length.EqualTo(1).And.Some.Contains("GT_EXTEND_VERTEX"));
            }
            finally
            {
                if (Directory.Exists(copy)) Directory.Delete(copy, true);
            }
        }
    }
}
