// The performance figures the README and the manual quote are the latest full run's: every ratio
// they quote must be a cell of the committed headline table (Tools~/bench/runs/h200/bench_table.md,
// "## Headline ratios", written by `gt bench --docs Tools~/bench/runs/h200` from the raw run, beside
// it), and the manual's summary tables must be what that command writes into performance.md, so a
// figure left from an older run fails here instead of reading as current.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class QuotedFiguresTests
    {
        const string Headline = "## Headline ratios";

        static string Read(params string[] parts) => File.ReadAllText(PackageRoot.Combine(parts));

        /// <summary>The headline run's full tables: with the bench tool, outside what the package ships.</summary>
        static readonly string[] BenchTable = { "Tools~", "bench", "runs", "h200", "bench_table.md" };

        /// <summary>The headline table's rows: path name -> ratio cells ("0.996x", ...).</summary>
        internal static Dictionary<string, string[]> HeadlineRows(string benchTable)
        {
            int at = benchTable.IndexOf(Headline, StringComparison.Ordinal);
            if (at < 0) throw new AssertionException($"bench_table.md has no \"{Headline}\" section: regenerate it with gt bench --docs");
            return TableRows(benchTable.Substring(at + Headline.Length));
        }

        /// <summary>The rows of the first Markdown table in <paramref name="text"/> (header and rule skipped).</summary>
        internal static Dictionary<string, string[]> TableRows(string text)
        {
            var rows = new Dictionary<string, string[]>();
            var lines = text.Split('\n').Select(l => l.Trim()).SkipWhile(l => !l.StartsWith("|", StringComparison.Ordinal))
                            .TakeWhile(l => l.StartsWith("|", StringComparison.Ordinal)).Skip(2);
            foreach (var l in lines)
            {
                var cells = l.Trim('|').Split('|').Select(c => c.Trim().Replace("**", "")).ToArray();
                rows[cells[0]] = cells.Skip(1).ToArray();
            }
            return rows;
        }

        /// <summary>Every ratio quoted as digits with a decimal point and an x ("0.996x", "3.4x").</summary>
        internal static string[] QuotedRatios(string text) =>
            Regex.Matches(text, @"(?<![\w.])\d+\.\d+x\b").Select(m => m.Value).ToArray();

        /// <summary>The quoted ratios missing from the headline table's cells.</summary>
        internal static string[] Stale(IEnumerable<string> quoted, Dictionary<string, string[]> headline)
        {
            var cells = new HashSet<string>(headline.Values.SelectMany(c => c));
            return quoted.Where(q => !cells.Contains(q)).Distinct().ToArray();
        }

        Dictionary<string, string[]> _headline;

        [OneTimeSetUp]
        public void ReadHeadline() => _headline = HeadlineRows(Read(BenchTable));

        [Test]
        public void ReadmePerformanceSentenceQuotesTheLatestRun()
        {
            string readme = Read("README.md");
            var m = Regex.Match(readme, @"Where compute shaders run.*?\(\[performance\]\(Documentation~/performance\.md\)\)", RegexOptions.Singleline);
            Assert.That(m.Success, "README.md: the performance sentence (from \"Where compute shaders run\" to its performance link) is missing");
            var quoted = QuotedRatios(m.Value);
            Assert.That(quoted.Length, Is.GreaterThanOrEqualTo(3), "README.md's performance sentence quotes fewer than 3 ratios");
            Assert.That(Stale(quoted, _headline), Is.Empty, "README.md quotes ratios that the committed headline table does not hold (stale?)");
        }

        [Test]
        public void ManualIndexQuotesTheLatestRun()
        {
            var quoted = QuotedRatios(Read("Documentation~", "index.md"));
            Assert.That(Stale(quoted, _headline), Is.Empty, "Documentation~/index.md quotes ratios that the committed headline table does not hold (stale?)");
        }

        [Test]
        public void PerformancePageInShortTableIsTheHeadlineTable()
        {
            string page = Read("Documentation~", "performance.md");
            int at = page.IndexOf("## In short", StringComparison.Ordinal);
            Assert.That(at, Is.GreaterThanOrEqualTo(0), "performance.md has no \"## In short\" section");
            var rows = TableRows(page.Substring(at));
            Assert.That(rows.Count, Is.GreaterThanOrEqualTo(5), "performance.md's In short table has fewer than 5 rows");
            foreach (var (name, cells) in rows)
            {
                Assert.That(_headline.ContainsKey(name), $"performance.md's In short row \"{name}\" is not a row of the headline table");
                Assert.That(cells, Is.EqualTo(_headline[name]), $"performance.md's In short row \"{name}\" differs from the headline table (stale?)");
            }
        }

        [Test]
        public void PerformancePageSummaryTablesAreWhatGtBenchDocsWrites()
        {
            string page = Read("Documentation~", "performance.md");
            Assert.That(BenchDocs.Rewrite(page, Read(BenchTable)), Is.EqualTo(page),
                "performance.md's summary tables (<!-- bench:NAME --> blocks) differ from the committed run's bench_table.md: run Tools~/gt bench --docs Tools~/bench/runs/h200");
        }

        [Test]
        public void AStaleSummaryTableIsFound()
        {
            string page = Read("Documentation~", "performance.md"), table = Read(BenchTable);
            const string row = "| cached adaptive | 16 | - | 1 | 64 | 0 | ";   // its triangle count follows
            int at = table.IndexOf(row, StringComparison.Ordinal);
            Assert.That(at, Is.GreaterThanOrEqualTo(0), "the committed run has no cached adaptive 1 px row at 16 tiles");
            string edited = table.Substring(0, at + row.Length) + "1" + table.Substring(at + row.Length);
            Assert.That(BenchDocs.Rewrite(page, edited), Is.Not.EqualTo(page), "a changed cell of the first table reaches the page's accuracy table");
            var e = Assert.Throws<ArgumentException>(() => BenchDocs.Rewrite("<!-- bench:headline -->\n| a |\n", table));
            Assert.That(e.Message, Does.Contain("/bench:headline"));
        }

        [Test]
        public void AStaleFigureIsFound()
        {
            var headline = TableRows("| path | 0.6M |\n| --- | ---: |\n| compute cache, still | 0.996x |\n");
            Assert.That(Stale(QuotedRatios("reads 0.996x at 0.6M and 1.013x before"), headline), Is.EqualTo(new[] { "1.013x" }));
            Assert.That(QuotedRatios("3.4x faster, 0.78x, v1.2 and 12.5x"), Is.EqualTo(new[] { "3.4x", "0.78x", "12.5x" }));
        }
    }
}
