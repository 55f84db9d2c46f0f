using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli bench-docs: the summary tables of the manual's performance page, taken from a run's full
    /// table (bench_table.md, which stays with the run under Tools~/bench/runs/). The page marks each
    /// summary block with <c>&lt;!-- bench:NAME --&gt;</c> ... <c>&lt;!-- /bench:NAME --&gt;</c>; everything
    /// between the marks is replaced, everything outside them is left as written. A block the page
    /// names but the table lacks, or a mark without its end, is refused before anything is written.
    /// </summary>
    static class BenchDocs
    {
        /// <summary>The blocks this command writes: name -> how the block is taken from the full table.</summary>
        static readonly Dictionary<string, Func<string, string>> Blocks = new Dictionary<string, Func<string, string>>(StringComparer.Ordinal)
        {
            // The headline ratios, verbatim.
            ["headline"] = t => FirstTable(t, "## Headline ratios"),
            // The first (accuracy against time) table at the plot's tile count: 16 tiles (the paper's
            // one-patch-a-draw rows too) and max factor 64; the max factor and the error in terrain
            // units left out (the full table has the other tile counts and max factors).
            ["accuracy"] = t => Select(FirstTable(t, "# gt bench"),
                r => r["max F"] == "64" && (r["tiles"] == "16" || r["method"] == "paper"),
                "max F", "max err (terrain units)"),
            // The Horizon levels' ground views against the tessellator's floor, less the goal (in the text) and a derived column.
            ["levels"] = t => Select(FirstTable(t, "## Horizon levels"), r => true, "goal", "levels' floor / floor"),
            // The tile count at a fixed triangle count, verbatim.
            ["tilecount"] = t => FirstTable(t, "### The tile count at a fixed triangle count"),
        };

        /// <summary>gt-cli bench-docs --table TABLE --page PAGE (no Args here: the rig's tests compile this file alone).</summary>
        public static int Run(string table, string page)
        {
            string text = File.ReadAllText(page), rewritten = Rewrite(text, File.ReadAllText(table));
            if (rewritten != text) File.WriteAllText(page, rewritten);
            Console.WriteLine($"{page}: {(rewritten == text ? "unchanged" : "summary tables rewritten")} from {table}");
            return 0;
        }

        /// <summary><paramref name="page"/> with every marked block replaced by its table from <paramref name="benchTable"/>.</summary>
        public static string Rewrite(string page, string benchTable)
        {
            var o = new StringBuilder();
            int at = 0, found = 0;
            while (true)
            {
                int open = page.IndexOf("<!-- bench:", at, StringComparison.Ordinal);
                if (open < 0) break;
                int openEnd = page.IndexOf("-->", open, StringComparison.Ordinal);
                if (openEnd < 0) throw new ArgumentException($"performance page: a \"<!-- bench:\" mark at character {open} is not closed");
                string name = page.Substring(open + 11, openEnd - open - 11).Trim();
                if (!Blocks.TryGetValue(name, out var make))
                    throw new ArgumentException($"performance page: unknown block \"{name}\" (known: {string.Join(", ", Blocks.Keys)})");
                string end = $"<!-- /bench:{name} -->";
                int close = page.IndexOf(end, openEnd, StringComparison.Ordinal);
                if (close < 0) throw new ArgumentException($"performance page: block \"{name}\" has no \"{end}\"");
                o.Append(page, at, openEnd + 3 - at).Append('\n').Append(make(benchTable)).Append(end);
                at = close + end.Length;
                found++;
            }
            if (found == 0) throw new ArgumentException("performance page: no \"<!-- bench:NAME -->\" block to write");
            return o.Append(page, at, page.Length - at).ToString();
        }

        /// <summary>The lines of the first Markdown table after the line starting with <paramref name="heading"/>, each ending in '\n'.</summary>
        static string FirstTable(string text, string heading)
        {
            var lines = text.Replace("\r\n", "\n").Split('\n');
            int h = Array.FindIndex(lines, l => l.StartsWith(heading, StringComparison.Ordinal));
            if (h < 0) throw new ArgumentException($"bench table: no section \"{heading}\" (regenerate it with gt bench --docs)");
            var rows = lines.Skip(h + 1).SkipWhile(l => !l.StartsWith("|", StringComparison.Ordinal))
                            .TakeWhile(l => l.StartsWith("|", StringComparison.Ordinal)).ToList();
            if (rows.Count < 3) throw new ArgumentException($"bench table: section \"{heading}\" has no table");
            return string.Concat(rows.Select(l => l + "\n"));
        }

        /// <summary>The rows of <paramref name="table"/> that <paramref name="keep"/> accepts, without the named columns.</summary>
        static string Select(string table, Func<Dictionary<string, string>, bool> keep, params string[] dropColumns)
        {
            var rows = table.TrimEnd('\n').Split('\n').Select(Cells).ToList();
            string[] header = rows[0];
            foreach (string c in dropColumns)
                if (!header.Contains(c)) throw new ArgumentException($"bench table: the first table has no column \"{c}\"");
            var kept = Enumerable.Range(0, header.Length).Where(i => !dropColumns.Contains(header[i])).ToArray();
            string Line(string[] cells) => "| " + string.Join(" | ", kept.Select(i => cells[i])) + " |\n";
            var o = new StringBuilder(Line(header)).Append(Line(rows[1]));
            foreach (var r in rows.Skip(2))
            {
                if (r.Length != header.Length) throw new ArgumentException($"bench table: a row of {r.Length} cells under {header.Length} columns");
                var byName = new Dictionary<string, string>(StringComparer.Ordinal);
                for (int i = 0; i < header.Length; i++) byName[header[i]] = r[i];
                if (keep(byName)) o.Append(Line(r));
            }
            return o.ToString();
        }

        static string[] Cells(string line) => line.Trim().Trim('|').Split('|').Select(c => c.Trim()).ToArray();
    }
}
