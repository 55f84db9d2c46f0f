using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Unity drops every file without a .meta from an immutable (Package Manager) package, and two
    /// assets with one GUID break references. These tests read the package as Unity would import it.
    /// </summary>
    [TestFixture]
    public class MetaFileTests
    {
        static readonly string[] RootFiles = { "package.json", "README.md", "CHANGELOG.md", "LICENSE.md" };
        static readonly string[] ImportedFolders = { "Runtime", "Shaders", "Editor", "Tests" };
        static readonly Regex GuidLine = new Regex(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        /// <summary>Everything Unity imports: root files, the imported folders and Samples~ content.</summary>
        static IEnumerable<string> ImportedPaths()
        {
            string root = PackageRoot.Path;
            foreach (var f in RootFiles)
                if (File.Exists(Path.Combine(root, f))) yield return Path.Combine(root, f);
            foreach (var top in ImportedFolders.Append("Samples~"))
            {
                string dir = Path.Combine(root, top);
                if (!Directory.Exists(dir)) continue;
                if (top != "Samples~") yield return dir;
                foreach (var p in Walk(dir)) yield return p;
            }
        }

        static IEnumerable<string> Walk(string dir)
        {
            foreach (var f in Directory.GetFiles(dir).OrderBy(x => x, StringComparer.Ordinal))
            {
                string name = Path.GetFileName(f);
                if (name.EndsWith(".meta", StringComparison.Ordinal) || name.StartsWith(".")) continue;
                yield return f;
            }
            foreach (var d in Directory.GetDirectories(dir).OrderBy(x => x, StringComparer.Ordinal))
            {
                string name = Path.GetFileName(d);
                if (name.EndsWith("~", StringComparison.Ordinal) || name.StartsWith(".")) continue;
                yield return d;
                foreach (var p in Walk(d)) yield return p;
            }
        }

        static string Rel(string p) => Path.GetRelativePath(PackageRoot.Path, p);

        [Test]
        public void EveryImportedFileAndFolderHasAMeta()
        {
            var missing = ImportedPaths().Where(p => !File.Exists(p + ".meta")).Select(Rel).ToList();
            TestContext.Out.WriteLine($"imported paths checked: {ImportedPaths().Count()}");
            Assert.That(missing, Is.Empty, "no .meta for: " + string.Join(", ", missing) +
                " (run Tools~/gt metas)");
        }

        [Test]
        public void EveryMetaIsWellFormedWithAUniqueGuid()
        {
            var seen = new Dictionary<string, string>();
            var problems = new List<string>();
            foreach (var p in ImportedPaths().Where(p => File.Exists(p + ".meta")))
            {
                string text = File.ReadAllText(p + ".meta");
                var m = GuidLine.Matches(text);
                if (!text.StartsWith("fileFormatVersion: 2\n", StringComparison.Ordinal))
                    problems.Add($"{Rel(p)}.meta: first line is not 'fileFormatVersion: 2'");
                if (m.Count != 1)
                {
                    problems.Add($"{Rel(p)}.meta: expected one 'guid: <32 lowercase hex>' line, found {m.Count}");
                    continue;
                }
                string guid = m[0].Groups[1].Value;
                if (guid.All(c => c == '0')) problems.Add($"{Rel(p)}.meta: guid is all zeros");
                if (seen.TryGetValue(guid, out var other))
                    problems.Add($"{Rel(p)}.meta: guid {guid} is also used by {other}.meta");
                else seen[guid] = Rel(p);
                bool isDir = Directory.Exists(p);
                if (isDir != text.Contains("folderAsset: yes"))
                    problems.Add($"{Rel(p)}.meta: folderAsset does not match ({(isDir ? "folder" : "file")})");
            }
            TestContext.Out.WriteLine($"guids checked: {seen.Count}");
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void NoMetaIsLeftWithoutItsAsset()
        {
            var orphans = new List<string>();
            foreach (var top in ImportedFolders.Append("Samples~"))
            {
                string dir = PackageRoot.Combine(top);
                if (!Directory.Exists(dir)) continue;
                foreach (var meta in Directory.GetFiles(dir, "*.meta", SearchOption.AllDirectories))
                {
                    string asset = meta.Substring(0, meta.Length - ".meta".Length);
                    if (!File.Exists(asset) && !Directory.Exists(asset)) orphans.Add(Rel(meta));
                }
            }
            Assert.That(orphans, Is.Empty, "orphan .meta files: " + string.Join(", ", orphans));
        }
    }
}
