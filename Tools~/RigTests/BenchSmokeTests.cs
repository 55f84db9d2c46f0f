// gt bench --quick on lavapipe: the benchmark runs end to end and its table is complete and sane.
// (Its timings are functional figures there; what is asserted is structure and accuracy trends.)
using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self), Order(2)]
    public class BenchSmokeTests
    {
        string _output;

        [OneTimeSetUp]
        public void RunQuickBench()
        {
            var psi = new ProcessStartInfo("bash", Path.Combine(PackageRoot.Path, "Tools~", "gt") + " bench --quick")
            {
                RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false,
                WorkingDirectory = PackageRoot.Path,
            };
            psi.Environment["VK_DRIVER_FILES"] = HarnessRun.LavapipeIcd;
            psi.Environment["VK_ICD_FILENAMES"] = HarnessRun.LavapipeIcd;
            using var p = Process.Start(psi);
            var err = p.StandardError.ReadToEndAsync();
            _output = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            TestContext.Out.WriteLine(_output);
            Assert.That(p.ExitCode, Is.EqualTo(0), "gt bench --quick failed:\n" + err.Result);
        }

        string[][] Rows(string method) => _output.Split('\n')
            .Where(l => l.StartsWith("| " + method, StringComparison.Ordinal))
            .Select(l => l.Trim().Trim('|').Split('|').Select(c => c.Trim()).ToArray()).ToArray();

        static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

        [Test]
        public void EveryMethodHasCompleteFiniteRows()
        {
            Assert.That(_output, Does.Not.Contain("incomplete"));
            foreach (var m in new[] { "adaptive", "uniform", "paper", "fallback", "cached adaptive", "cached uniform" })
            {
                var rows = Rows(m);
                Assert.That(rows.Length, Is.GreaterThanOrEqualTo(2), m);
                foreach (var r in rows)
                {
                    Assert.That(D(r[6]), Is.GreaterThan(0), $"{m}: triangles");
                    Assert.That(D(r[7]), Is.GreaterThan(0), $"{m}: shader invocations");
                    Assert.That(D(r[8]), Is.GreaterThan(0), $"{m}: GPU time");
                    Assert.That(D(r[9]), Is.GreaterThan(0).And.LessThan(1000), $"{m}: max error px");
                    Assert.That(D(r[10]), Is.GreaterThan(0).And.LessThanOrEqualTo(D(r[9])), $"{m}: RMS <= max");
                }
            }
            Assert.That(_output, Does.Contain("range-only / nothing changes"));
            Assert.That(_output, Does.Contain("/ static mesh"));
            Assert.That(_output, Does.Contain("same vertices, same frag"), "the fair static mesh section");
            Assert.That(_output, Does.Contain("## Headline ratios"), "the headline table the manual quotes");
            Assert.That(_output, Does.Contain("## The fair baseline and the floor"), "the fair baseline section");
            Assert.That(_output, Does.Contain("## Motion users make"), "the motion section");
            Assert.That(_output, Does.Not.Contain("| (incomplete) |"), "every fair static size ran");
            Assert.That(_output, Does.Match(@"\| domain stage, tiled noise \+ colour \| [0-9.]+x \|"), "the tiled noise's job ran (GT_NOISE_TABLE, its table bound)");
        }

        [Test]
        public void DomainStageBreakdownTimesEveryPart()
        {
            // Tools~/rig/bench_domain_parts.hlsl: one job a part (BenchPlan.DomainParts), each a GPU time.
            int at = _output.IndexOf("## Where the domain stage's time goes", StringComparison.Ordinal);
            Assert.That(at, Is.GreaterThanOrEqualTo(0), "the breakdown section");
            string section = _output.Substring(at);
            int end = section.IndexOf("\n## ", 5, StringComparison.Ordinal);
            if (end > 0) section = section.Substring(0, end);
            var rows = section.Split('\n').Where(l => l.StartsWith("| ", StringComparison.Ordinal) && !l.StartsWith("| job", StringComparison.Ordinal) && !l.StartsWith("| ---", StringComparison.Ordinal))
                .Select(l => l.Trim().Trim('|').Split('|').Select(c => c.Trim()).ToArray()).ToArray();
            foreach (var name in new[] { "terrain", "full", "no_lookup", "no_deriv", "no_octaves", "no_normal", "plain", "minimal", "tess-floor" })
                Assert.That(rows.Any(r => r[0] == name), Is.True, $"breakdown row {name}");
            Assert.That(rows.Length, Is.GreaterThanOrEqualTo(17), "terrain, 15 parts (two of them candidates reading a table), floor");
            foreach (var r in rows)
                Assert.That(double.TryParse(r[2], NumberStyles.Float, CultureInfo.InvariantCulture, out double ms) && ms > 0, Is.True, $"{r[0]}: GPU ms '{r[2]}' (the part's job did not run)");
            Assert.That(section, Does.Match(@"against the minimal Gregory evaluator: [\d.]+ vs [\d.]+ ms"), "the plain stage against the minimal evaluator");
        }

        [Test]
        public void VertexCacheRowsRunTheComputePrePassAndMatchTheirFactors()
        {
            var rows = Rows("cached adaptive").Concat(Rows("cached uniform")).ToArray();
            Assert.That(rows.Length, Is.GreaterThanOrEqualTo(5), "cached adaptive (3 targets) and cached uniform (2 factors)");
            foreach (var r in rows)
            {
                Assert.That(D(r[12]), Is.GreaterThan(0), $"{r[0]} {r[2]} {r[3]}: compute ms");
                Assert.That(D(r[12]), Is.LessThanOrEqualTo(D(r[8])), $"{r[0]} {r[2]} {r[3]}: the pre-pass is part of the frame");
            }
            foreach (var r in Rows("adaptive").Concat(Rows("uniform")))
                Assert.That(r[12], Is.EqualTo("-"), "no compute column for the domain-stage rows");
            // Cached uniform at an odd F draws what fractional_odd draws: the same triangles and error.
            foreach (var c in Rows("cached uniform"))
            {
                var u = Rows("uniform").Single(r => r[2] == c[2] && r[5] == c[5]);
                Assert.That(D(c[6]), Is.EqualTo(D(u[6])), $"F {c[2]}: triangles");
                Assert.That(D(c[9]), Is.EqualTo(D(u[9])).Within(1e-6).Percent, $"F {c[2]}: max error px");
            }
            Assert.That(_output, Does.Contain("cached adaptive needs"), "the 4x goal for the vertex cache");
            // The tessellator draws the integer-partitioning count of the dumped factors (rings included).
            var model = System.Text.RegularExpressions.Regex.Match(_output, @"count of their dumped factors \(transition rings included\): largest difference ([0-9.eE+-]+)%");
            Assert.That(model.Success, Is.True, "triangle model line");
            Assert.That(D(model.Groups[1].Value), Is.LessThan(0.1), "GPU triangles vs the integer model, percent");
            // The kernel's factors are Core's mirror made integer: at most a ceil flip where a float factor sits at an integer.
            var core = System.Text.RegularExpressions.Regex.Match(_output, @"made integer \(VertexCache.IntegerFactors\): (\d+) of (\d+) drawn tiles differ \(culling or a factor\), largest factor difference ([0-9.eE+-]+)");
            Assert.That(core.Success, Is.True, "factor comparison line");
            Assert.That(D(core.Groups[2].Value), Is.GreaterThan(0));
            Assert.That(D(core.Groups[1].Value), Is.LessThanOrEqualTo(0.02 * D(core.Groups[2].Value)), "tiles whose cache factors differ from Core's");
            Assert.That(D(core.Groups[3].Value), Is.LessThanOrEqualTo(1), "largest factor difference");
            // The inspector's estimate (Core's mirror of the factors, counted) is what each adaptive job drew.
            foreach (string path in new[] { "adaptive (fractional_odd)", "cached adaptive (integer)" })
            {
                var est = System.Text.RegularExpressions.Regex.Match(_output, @"clipping invocations, " + System.Text.RegularExpressions.Regex.Escape(path) + @" jobs: (\d+) of (\d+) exact, largest difference ([0-9.eE+-]+)%");
                Assert.That(est.Success, Is.True, path + ": estimate line");
                Assert.That(D(est.Groups[2].Value), Is.GreaterThan(0), path + ": jobs compared");
                Assert.That(D(est.Groups[3].Value), Is.LessThan(1), path + ": the estimate against the GPU's triangles, percent");
            }
            Assert.That(_output, Does.Contain("The vertex cache (GT_VERTEX_CACHE) against the same fair static meshes"));
            Assert.That(_output, Does.Match(@"\| fs_m8_f7 \(uniform\) \| 8 \| 7 \| \d+ \|"), "cached fair row ran");
            Assert.That(_output, Does.Match(@"\| vc_m8_s8x7 \(adaptive\) \| 8 \| [0-9.]+ \| \d+ \|"), "cached adaptive fair row ran");
            // The tile-count knob: the cached adaptive row with its error at the plan's view, which
            // the adaptive factors keep near the target (the sweep's worst overshoot is 1.5x).
            var tile = System.Text.RegularExpressions.Regex.Match(_output, @"\| fs_m8_f7 \| 8 \| ([0-9.]+) \| \d+ \| ([0-9.eE+-]+) \| ([0-9.eE+-]+) \| [0-9.]+x \|");
            Assert.That(tile.Success, Is.True, "tile-count row");
            Assert.That(D(tile.Groups[2].Value), Is.GreaterThan(0).And.LessThan(2 * D(tile.Groups[1].Value)), "tile-count row: max error px against the target");
            Assert.That(D(tile.Groups[3].Value), Is.GreaterThan(0).And.LessThan(D(tile.Groups[2].Value)), "tile-count row: RMS below the max");
        }

        [TestCase("adaptive")]
        [TestCase("cached adaptive")]
        public void SmallerPixelTargetsGiveSmallerErrorsAndMoreTriangles(string method)
        {
            var rows = Rows(method + " |").OrderByDescending(r => D(r[3])).ToArray();   // target px, large to small
            Assert.That(rows.Length, Is.GreaterThanOrEqualTo(3));
            for (int i = 1; i < rows.Length; i++)
            {
                Assert.That(D(rows[i][6]), Is.GreaterThan(D(rows[i - 1][6])), $"triangles at target {rows[i][3]} vs {rows[i - 1][3]}");
                Assert.That(D(rows[i][9]), Is.LessThan(D(rows[i - 1][9])), $"max error at target {rows[i][3]} vs {rows[i - 1][3]}");
                Assert.That(D(rows[i][10]), Is.LessThan(D(rows[i - 1][10])), $"RMS error at target {rows[i][3]} vs {rows[i - 1][3]}");
            }
            // Uniform factors: error falls roughly as 1 / F^2.
            var uni = Rows(method == "adaptive" ? "uniform |" : "cached uniform |").OrderBy(r => D(r[2])).ToArray();
            Assert.That(uni.Length, Is.GreaterThanOrEqualTo(2));
            for (int i = 1; i < uni.Length; i++)
                Assert.That(D(uni[i][9]), Is.LessThan(D(uni[i - 1][9])));
        }

        [Test]
        public void FairBaselineFloorAndMotionRowsRan()
        {
            // The fair static mesh in Forsyth's order, row by row and in strips, each with its
            // vertex-stage runs per vertex; the floor; the motion path with its dispatches.
            var baseline = Rows("8 | 7 |");
            Assert.That(baseline.Length, Is.GreaterThanOrEqualTo(1), "the fair baseline row of 8 tiles at F 7");
            var b = baseline[0];
            foreach (int k in new[] { 3, 4, 5, 6, 7, 8, 9, 10, 11 })
                Assert.That(D(b[k]), Is.GreaterThan(0), $"fair baseline column {k}");
            var motion = Rows("pan-cell");
            Assert.That(motion.Length, Is.EqualTo(1), "the pan-cell motion row");
            Assert.That(D(motion[0][2]), Is.GreaterThan(0), "domain stage triangles under the pan");
            Assert.That(D(motion[0][6]), Is.GreaterThan(0), "compute cache triangles under the pan");
            Assert.That(motion[0][7], Is.EqualTo("4"), "the camera follows the range: the kernels run in all 4 frames");
            Assert.That(_output, Does.Not.Contain("| compute cache, panning (anchored tiles) | - |"), "the headline's first row ran");
        }

        [Test]
        public void HorizonLevelsRowRanBesideItsFloors()
        {
            // The walking ground view (camera and levels moving every frame), the levels' own floor
            // and the tessellator's floor at the triangles the levels drew.
            var rows = Rows("100 km, walk");
            Assert.That(rows.Length, Is.EqualTo(1), "the 100 km walking row of ## Horizon levels");
            var r = rows[0];
            double triangles = D(r[1].Replace(",", ""));
            Assert.That(triangles, Is.GreaterThan(0), "levels' triangles");
            foreach (int k in new[] { 2, 3 }) Assert.That(D(r[k]), Is.GreaterThan(0), $"column {k}: GPU ms");
            var floor = System.Text.RegularExpressions.Regex.Match(r[4], @"^([0-9.]+) \((\d+) x (\d+), ([0-9,]+)\)$");
            Assert.That(floor.Success, $"floor cell '{r[4]}': ms (tiles x F, triangles)");
            Assert.That(D(floor.Groups[4].Value.Replace(",", "")), Is.EqualTo(triangles).Within(5).Percent, "the floor's triangles match the levels'");
            Assert.That(r[5], Does.Match(@"^[0-9.]+x$"), "levels / floor");
        }
    }
}
