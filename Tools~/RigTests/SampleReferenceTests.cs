using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The sample's hand-written YAML must open in Unity: every asset reference ({fileID, guid}) must
    /// name a .meta of this package or a Unity built-in, and every local {fileID: N} an object of the
    /// same file.
    /// </summary>
    [TestFixture]
    public class SampleReferenceTests
    {
        /// <summary>GUIDs Unity reserves for its own resources (they have no .meta anywhere).</summary>
        static readonly Dictionary<string, string> BuiltIn = new Dictionary<string, string>
        {
            ["0000000000000000e000000000000000"] = "unity_builtin_extra (built-in extra resources)",
            ["0000000000000000f000000000000000"] = "unity default resources (built-in meshes, fonts)",
        };
        static readonly string[] YamlExtensions = { ".unity", ".mat", ".asset", ".prefab" };
        static readonly Regex Reference = new Regex(@"\{fileID: (-?\d+)(?:, guid: ([0-9a-f]{32}), type: \d+)?\}");
        static readonly Regex Anchor = new Regex(@"^--- !u!\d+ &(-?\d+)", RegexOptions.Multiline);
        static readonly Regex MetaGuid = new Regex(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        static IEnumerable<string> SampleYamlFiles()
        {
            string dir = PackageRoot.Combine("Samples~");
            if (!Directory.Exists(dir)) return Array.Empty<string>();
            return Directory.GetFiles(dir, "*", SearchOption.AllDirectories)
                .Where(f => YamlExtensions.Contains(Path.GetExtension(f))).OrderBy(f => f, StringComparer.Ordinal);
        }

        static HashSet<string> PackageGuids()
        {
            var guids = new HashSet<string>();
            foreach (var meta in PackageRoot.FilesUnityImports("*.meta"))
            {
                if (meta.Contains(Path.DirectorySeparatorChar + ".")) continue;
                var m = MetaGuid.Match(File.ReadAllText(meta));
                if (m.Success) guids.Add(m.Groups[1].Value);
            }
            return guids;
        }

        [Test]
        public void SampleHasYamlFiles()
        {
            var files = SampleYamlFiles().ToList();
            TestContext.Out.WriteLine($"sample YAML files: {files.Count}");
            Assert.That(files.Select(Path.GetExtension), Does.Contain(".unity").And.Contain(".mat").And.Contain(".asset"));
        }

        [Test]
        public void EveryReferenceResolves()
        {
            var guids = PackageGuids();
            var problems = new List<string>();
            int total = 0, resolved = 0;
            foreach (var file in SampleYamlFiles())
            {
                string text = File.ReadAllText(file);
                string rel = Path.GetRelativePath(PackageRoot.Path, file);
                if (!text.StartsWith("%YAML 1.1", StringComparison.Ordinal)) problems.Add($"{rel}: does not start with %YAML 1.1");
                var anchors = new HashSet<string>(Anchor.Matches(text).Select(m => m.Groups[1].Value));
                foreach (Match m in Reference.Matches(text))
                {
                    total++;
                    string fileId = m.Groups[1].Value, guid = m.Groups[2].Value;
                    bool ok;
                    if (guid.Length == 0) ok = fileId == "0" || anchors.Contains(fileId);
                    else ok = guids.Contains(guid) || BuiltIn.ContainsKey(guid);
                    if (ok) resolved++;
                    else problems.Add($"{rel}: {m.Value} does not resolve");
                }
            }
            TestContext.Out.WriteLine($"references resolved: {resolved}/{total}");
            Assert.That(total, Is.GreaterThan(0));
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }
    }
}
