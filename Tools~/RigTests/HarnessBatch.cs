// gt-harness --batch (Tools~/harness/src/batch.hpp): many harness runs in a few processes, one device
// and each distinct pipeline created once per process, each run's output as its own HarnessRun.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    internal static class HarnessBatch
    {
        /// <summary>
        /// Runs each argument list as <see cref="HarnessRun.Harness"/> would (the forward pass's state first),
        /// split in order over <paramref name="processes"/> batch files in <paramref name="work"/> run side
        /// by side; the result of each run, in the order given.
        /// </summary>
        public static HarnessRun[] Run(string work, IList<string[]> runs, int processes = 2)
        {
            var results = new HarnessRun[runs.Count];
            int per = Math.Max(1, (runs.Count + processes - 1) / processes);
            Parallel.For(0, processes, new ParallelOptions { MaxDegreeOfParallelism = processes }, b =>
            {
                int lo = b * per, hi = Math.Min(runs.Count, lo + per);
                if (lo >= hi) return;
                string file = Path.Combine(work, "batch" + b + ".txt");
                File.WriteAllLines(file, Enumerable.Range(lo, hi - lo).Select(i => Line(runs[i])));
                HarnessRun[] parts = Split(HarnessRun.Start(HarnessRun.HarnessPath(), new[] { "--batch", file }), hi - lo);
                Array.Copy(parts, 0, results, lo, parts.Length);
            });
            return results;
        }

        /// <summary>One batch line: the run's options, tab-separated.</summary>
        static string Line(string[] args)
        {
            string[] all = HarnessRun.PassStateArgs(args.Contains("--tesc") ? "tessellated" : "fallback").Concat(args).ToArray();
            Assert.That(all.Any(a => a.Contains('\t') || a.Contains('\n')), Is.False, "a batch option holds a tab or a line break");
            return string.Join("\t", all);
        }

        /// <summary>
        /// The output of a batch process cut into its runs ("batch run I" .. "batch exit I CODE"); a run
        /// the output does not close fails with the whole output and the process's error text.
        /// </summary>
        public static HarnessRun[] Split(HarnessRun whole, int count)
        {
            var runs = new HarnessRun[count];
            HarnessRun current = null;
            var lines = new List<string>();
            foreach (string line in whole.Stdout.Split('\n'))
            {
                string[] w = line.Split(' ');
                if (w.Length >= 3 && w[0] == "batch" && w[1] == "run")
                {
                    current = new HarnessRun { ExitCode = -1 };
                    lines.Clear();
                }
                else if (current != null && w.Length >= 4 && w[0] == "batch" && w[1] == "error")
                    current.Stderr += "gt-harness: error: " + string.Join(" ", w.Skip(3)) + "\n";
                else if (current != null && w.Length == 4 && w[0] == "batch" && w[1] == "exit")
                {
                    int index = int.Parse(w[2]);
                    current.ExitCode = int.Parse(w[3]);
                    current.Stdout = string.Join("\n", lines) + "\n";
                    if (index < count) runs[index] = current;
                    current = null;
                }
                else if (current != null) lines.Add(line);
            }
            for (int i = 0; i < count; i++)
                runs[i] ??= new HarnessRun { ExitCode = whole.ExitCode == 0 ? -1 : whole.ExitCode, Stdout = whole.Stdout,
                                             Stderr = $"batch run {i} has no output of its own (exit {whole.ExitCode}):\n" + whole.Stderr };
            return runs;
        }
    }
}
