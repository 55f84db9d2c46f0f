using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// What a user downloads stays small: the files a published tarball holds (the package folder
    /// less what .npmignore and npm itself leave out), without the sample's assets (Samples~, which
    /// Unity imports only on request), add up to less than the ceiling below. The walk is done here rather than
    /// by npm, which the CI machine does not install; it follows the .npmignore rules this package
    /// uses and refuses any it does not implement.
    /// </summary>
    [TestFixture]
    public class PackageSizeTests
    {
        /// <summary>
        /// Issue 24's goal: under 2 MB (2,000,000 bytes) without the sample's assets. Measurements,
        /// full bench tables and records live with the bench tool under Tools~, which is not packed.
        /// </summary>
        const long LimitBytes = 2_000_000;

        /// <summary>What npm leaves out of every package whatever .npmignore says (npm-packlist's defaults).</summary>
        static readonly string[] NpmAlwaysIgnores =
        {
            ".git", ".svn", ".hg", "CVS", "node_modules", ".npmrc", ".DS_Store", "npm-debug.log",
            "package-lock.json", ".lock-wscript", ".wafpickle-*", "._*", "*.orig", ".*.swp", "config.gypi",
        };

        [Test]
        public void ThePackageWithoutTheSampleIsUnderTwoMegabytes()
        {
            var files = PackedFiles(PackageRoot.Path);
            Assert.That(files.Count, Is.GreaterThan(100), "files found");
            Assert.That(files.Any(f => f.path.StartsWith("Tools~/")), Is.False, ".npmignore leaves Tools~ out");
            var shipped = files.Where(f => !f.path.StartsWith("Samples~/")).ToList();
            long total = shipped.Sum(f => f.bytes);
            string largest = string.Join("\n", shipped.OrderByDescending(f => f.bytes).Take(12).Select(f => $"  {f.bytes,9} {f.path}"));
            TestContext.Out.WriteLine($"packed without Samples~: {total} bytes in {shipped.Count} files; largest:\n{largest}");
            Assert.That(total, Is.LessThan(LimitBytes),
                $"the package without Samples~ is {total} bytes (limit {LimitBytes}); largest files:\n{largest}");
        }

        [Test]
        public void AnIgnoreRuleTheWalkDoesNotImplementIsRefused()
        {
            var e = Assert.Throws<InvalidOperationException>(() => ParseIgnore(new[] { "Tools~/", "!Tools~/keep.md" }));
            Assert.That(e.Message, Does.Contain("!Tools~/keep.md"));
        }

        /// <summary>The files npm would pack from <paramref name="root"/>: (path relative to it with '/', bytes).</summary>
        internal static List<(string path, long bytes)> PackedFiles(string root)
        {
            string ignoreFile = Path.Combine(root, ".npmignore");
            var rules = ParseIgnore(File.Exists(ignoreFile) ? File.ReadAllLines(ignoreFile) : Array.Empty<string>())
                .Concat(NpmAlwaysIgnores.Select(p => ToRule(p, false, false))).ToList();
            var result = new List<(string, long)>();
            Walk(new DirectoryInfo(root), "", rules, result);
            return result;
        }

        static void Walk(DirectoryInfo dir, string prefix, List<(Regex name, bool dirOnly, bool anchored)> rules, List<(string, long)> into)
        {
            foreach (FileSystemInfo e in dir.EnumerateFileSystemInfos().OrderBy(e => e.Name, StringComparer.Ordinal))
            {
                if (e.Attributes.HasFlag(FileAttributes.ReparsePoint)) continue;   // npm packs no links
                bool isDir = e is DirectoryInfo;
                string rel = prefix + e.Name;
                if (rules.Any(r => (!r.dirOnly || isDir) && r.name.IsMatch(r.anchored ? rel : e.Name))) continue;
                if (isDir) Walk((DirectoryInfo)e, rel + "/", rules, into);
                else into.Add((rel, ((FileInfo)e).Length));
            }
        }

        /// <summary>
        /// The subset of gitignore syntax this walk implements: comments, blank lines, names and
        /// globs with <c>*</c> and <c>?</c>, a trailing <c>/</c> (folders only), a leading <c>/</c> or an
        /// inner <c>/</c> (anchored at the root). Anything else (negation, <c>**</c>, character
        /// classes, escapes) throws, naming the line, rather than be read wrong.
        /// </summary>
        internal static List<(Regex name, bool dirOnly, bool anchored)> ParseIgnore(IEnumerable<string> lines)
        {
            var rules = new List<(Regex, bool, bool)>();
            foreach (string raw in lines)
            {
                string line = raw.Trim();
                if (line.Length == 0 || line.StartsWith("#")) continue;
                if (line.StartsWith("!") || line.Contains("**") || line.IndexOfAny(new[] { '[', ']', '\\' }) >= 0)
                    throw new InvalidOperationException($".npmignore rule '{line}' uses syntax PackageSizeTests does not implement");
                bool dirOnly = line.EndsWith("/");
                string p = line.TrimEnd('/');
                bool anchored = p.Contains("/");
                rules.Add(ToRule(p.TrimStart('/'), dirOnly, anchored));
            }
            return rules;
        }

        static (Regex, bool, bool) ToRule(string glob, bool dirOnly, bool anchored) =>
            (new Regex("^" + Regex.Escape(glob).Replace(@"\*", "[^/]*").Replace(@"\?", "[^/]") + "$", RegexOptions.CultureInvariant), dirOnly, anchored);
    }
}
