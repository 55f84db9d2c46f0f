// Issue 39, deliverable 8: every numeric option of gt and gt-cli refuses zero, negative, non-finite,
// absurdly large and non-numeric values outside its range with "CMD: --OPTION VALUE ... (RANGE)",
// exit 2, before any work (nothing written, well under a second), and never as an internal error.
// Options is the list of those options and their ranges; Coverage fails when a command reads a
// numeric option that the list lacks. Runs the built gt-cli (gt setup) and the gt scripts.
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
    // Each probe is its own process in its own folder: two at a time keep both cores busy, and the
    // fixture shares the lane with the other slow ones (.build/rig-options is its own).
    [TestFixture, Parallelizable(ParallelScope.Self | ParallelScope.Children), Order(9)]
    public class RigOptionTests
    {
        /// <summary>One number of an option: [Lo, Hi] (above Lo when Open), integers when Whole, 0 refused when NotZero.</summary>
        public sealed class Part
        {
            public string Label, Text;
            public bool Whole, Open, NotZero;
            public double Lo, Hi;

            public bool Holds(double v) => (Open ? v > Lo : v >= Lo) && v <= Hi && !(NotZero && v == 0) && (!Whole || v == Math.Floor(v));

            /// <summary>"[label] [int] [&gt;]lo..hi[, not 0]", as the messages print the range.</summary>
            public static Part Parse(string spec)
            {
                var m = Regex.Match(spec, @"^(?:(?<label>[a-z]+) )?(?<int>int )?(?<range>(?<open>>)?(?<lo>-?[0-9.]+)\.\.(?<hi>-?[0-9.]+)(?<nz>, not 0)?)$");
                if (!m.Success) throw new ArgumentException("bad range spec: " + spec);
                return new Part
                {
                    Label = m.Groups["label"].Success ? m.Groups["label"].Value : null, Text = m.Groups["range"].Value,
                    Whole = m.Groups["int"].Success, Open = m.Groups["open"].Success, NotZero = m.Groups["nz"].Success,
                    Lo = double.Parse(m.Groups["lo"].Value, CultureInfo.InvariantCulture), Hi = double.Parse(m.Groups["hi"].Value, CultureInfo.InvariantCulture),
                };
            }
        }

        /// <summary>A numeric option: Tool "gt-cli" or "gt", the command, the option, its numbers, and a valid value (for the other numbers of a multi-number option).</summary>
        public sealed class Option
        {
            public string Tool, Command, Name, Valid;
            public Part[] Parts;
            public bool List;
            public char Separator = ',';
            public override string ToString() => $"{Tool} {Command} --{Name}";
        }

        static Option Cli(string cmd, string name, string spec, string valid = null) => Make("gt-cli", cmd, name, spec, valid);
        static Option Gt(string cmd, string name, string spec, string valid = null) => Make("gt", cmd, name, spec, valid);

        /// <summary>spec: one part, "list PART" (a comma-separated list), "PART; PART; ..." (labelled numbers), or "size" (WIDTHxHEIGHT).</summary>
        static Option Make(string tool, string cmd, string name, string spec, string valid)
        {
            var o = new Option { Tool = tool, Command = cmd, Name = name, Valid = valid };
            if (spec == "size") { o.Parts = new[] { Part.Parse("width int 1..16384"), Part.Parse("height int 1..16384") }; o.Separator = 'x'; o.Valid = "64x64"; }
            else if (spec.StartsWith("list ")) { o.Parts = new[] { Part.Parse(spec.Substring(5)) }; o.List = true; }
            else o.Parts = spec.Split("; ").Select(Part.Parse).ToArray();
            return o;
        }

        const string Noise = "amplitude -1000..1000; frequency >0..16777216; alpha >1..1024; beta >0..1024", NoiseValid = "0.004,16,2,2";
        const string Unit4 = "c 0..1; d 0..1; g 0..1; h 0..1";
        const string Xyz = "x -1000..1000; y -1000..1000; z -1000..1000";

        static IEnumerable<Option> Scene(string cmd) => new[]
        {
            Cli(cmd, "range", Unit4, "0,0,1,1"), Cli(cmd, "anchor-at", Unit4, "0,0,1,1"), Cli(cmd, "tiles", "int 1..1024"),
            Cli(cmd, "max-factor", "1..64"), Cli(cmd, "target-pixels", ">0..16384"), Cli(cmd, "factor", "0..64"),
            Cli(cmd, "noise", Noise, NoiseValid), Cli(cmd, "octaves", "int 0..16"), Cli(cmd, "gamma", "-1000..1000, not 0"),
            Cli(cmd, "noise-vertices", "0..16777216"), Cli(cmd, "width", "int 1..16384"), Cli(cmd, "height", "int 1..16384"),
        };

        /// <summary>Every numeric option of gt-cli and gt, with the range it accepts.</summary>
        public static readonly Option[] Options = new[]
        {
            Cli("demo-grid", "columns", "int 1..1024"), Cli("demo-grid", "rows", "int 1..1024"), Cli("demo-grid", "samples", "int 2..16384"),
            Cli("demo-grid", "metres-across", ">0..100000000"), Cli("demo-grid", "exaggerate", ">0..1000"),
            Cli("eval", "noise", Noise, NoiseValid), Cli("eval", "octaves", "int 0..16"), Cli("eval", "span", ">0..0.5"),
            Cli("error", "max-cells", "int 1..67108864"),
            Cli("bench-plan", "width", "int 1..16384"), Cli("bench-plan", "height", "int 1..16384"),
            Cli("bench-plan", "frames", "int 1..100000"), Cli("bench-plan", "warmup", "int 0..100000"),
            Cli("lod-scene", "terrain-m", ">0..100000000"), Cli("lod-scene", "eye-m", ">0..100000000"), Cli("lod-scene", "finest-m", ">0..100000000"),
            Cli("lod-scene", "tiles", "int 2..64"), Cli("lod-scene", "factor", "int 0..64"), Cli("lod-scene", "target-pixels", ">0..16384"),
            Cli("lod-scene", "segment-pixels", ">0..16384"), Cli("lod-scene", "width", "int 1..16384"), Cli("lod-scene", "height", "int 1..16384"),
            Cli("lod-scene", "ground", "x 0..1; y 0..1", "0.5,0.5"), Cli("lod-scene", "max-cells", "int 1..67108864"), Cli("lod-scene", "relief-m", "0..100000000"),
            Cli("snow-scene", "cap", ">0..1000"), Cli("snow-scene", "dt", ">0..3600"), Cli("snow-scene", "eye", Xyz, "0,1,0"),
            Cli("snow-scene", "factor", "0..64"), Cli("snow-scene", "fov", ">0..179"), Cli("snow-scene", "height", "int 1..16384"),
            Cli("snow-scene", "height-scale", ">0..1000"), Cli("snow-scene", "light", Xyz, "0,1,0"), Cli("snow-scene", "noise-amplitude", "-1000..1000"),
            Cli("snow-scene", "patches", "int 1..64"), Cli("snow-scene", "resolutions", "list int 64..4096", "256"), Cli("snow-scene", "scale", "0..1000"),
            Cli("snow-scene", "steps", "int 1..100000"), Cli("snow-scene", "target", Xyz, "0,0,0"), Cli("snow-scene", "tiles", "int 1..64"),
            Cli("snow-scene", "width", "int 1..16384"), Cli("snow-scene", "wind", "x -1000..1000; y -1000..1000", "1,0"),
            Cli("pack", "orbit", "frames int 1..100000; degrees -90..90", "4,10"),
            Cli("estimate", "repeat", "int 1..100000"), Cli("estimate", "target", ">0..16384"), Cli("estimate", "tiles", "list int 1..64", "16"),
            Cli("fit-bench", "patches", "int 1..1024"), Cli("fit-bench", "size", "int 2..16384"),
            Cli("fit-reference", "patches", "int 1..1024"), Cli("fit-reference", "crop", "int 0..16384"),
            Cli("query-bench", "collider-samples", "int 2..255"), Cli("query-bench", "collider-spacing", ">0..100000000"),
            Cli("query-bench", "noise", Noise, NoiseValid), Cli("query-bench", "octaves", "int 0..16"), Cli("query-bench", "seconds", ">0..3600"),
            Cli("query-bench", "size", ">0..100000000"), Cli("query-bench", "threads", "int 1..1024"),
            Cli("lod-cpu-bench", "frames", "int 1..100000000"), Cli("lod-cpu-bench", "rounds", "int 1..1000"),
            Cli("lod-cache-churn", "frames", "int 1..100000"),
            Cli("sculpt-bench", "dabs", "int 1..100000"), Cli("sculpt-bench", "patches", "int 2..1024"), Cli("sculpt-bench", "radius-patches", ">0..1024"),
            Cli("jitter", "center", "x 0..1; y 0..1", "0.5,0.5"), Cli("jitter", "factor", "int 1..64"), Cli("jitter", "noise", Noise, NoiseValid),
            Cli("jitter", "octaves", "int 0..16"), Cli("jitter", "pan", "-16384..16384"), Cli("jitter", "pixels", ">0..16384"),
            Cli("jitter", "tiles", "int 1..64"), Cli("jitter", "widths", "list >0..1", "0.01"),
            Gt("demo", "tiles", "int 1..1024"), Gt("demo", "factor", "0..64"), Gt("demo", "width", "int 1..16384"), Gt("demo", "height", "int 1..16384"),
            Gt("bench_patch_layout", "rounds", "int 1..1000"), Gt("bench_patch_layout", "frames", "int 1..100000"), Gt("bench_patch_layout", "factor", "0..64"),
            Gt("bench_patch_layout", "tiles", "int 1..1024"), Gt("bench_patch_layout", "width", "int 1..16384"), Gt("bench_patch_layout", "height", "int 1..16384"),
            Gt("bench_patch_layout-device", "rounds", "int 1..1000"), Gt("bench_patch_layout-device", "frames", "int 1..100000"),
            Gt("fit-bench", "patches", "list int 1..1024", "16"), Gt("fit-bench", "sizes", "list int 2..16384", "257"),
            Gt("fit-bench", "scale-patches", "list int 1..1024", "32"), Gt("fit-bench", "legacy-sizes", "list int 2..16384", "1025"),
            Gt("lod-bench", "frames", "int 1..100000"), Gt("lod-carry", "terrains", "list >0..100000000", "100000"),
            Gt("lod-device", "frames", "int 1..100000"), Gt("lod-device", "rounds", "int 1..1000"),
            Gt("snow-carry", "resolutions", "list int 64..4096", "256"), Gt("snow-carry", "steps", "int 1..100000"),
            Gt("snow-carry", "dt", ">0..3600"), Gt("snow-carry", "size", "size"),
            Gt("snow-device", "frames", "int 1..100000"),
            Gt("shaders", "jobs", "int 1..256"), Gt("shaderlab", "jobs", "int 1..256"),
            Gt("pipeline_pass", "sun-elevation", "-90..90"), Gt("pipeline_pass", "sun-azimuth", "-360..360"),
            Gt("pipeline_pass", "shadow-sun-elevation", "-90..90"), Gt("pipeline_pass", "shadow-sun-azimuth", "-360..360"),
            Gt("pipeline_pass", "object-yaw", "-360..360"),
            Gt("pipeline_pass_hdrp", "sun-elevation", "-90..90"), Gt("pipeline_pass_hdrp", "sun-azimuth", "-360..360"),
            Gt("pipeline_pass_hdrp", "shadow-sun-elevation", "-90..90"), Gt("pipeline_pass_hdrp", "shadow-sun-azimuth", "-360..360"),
            Gt("pipeline_pass_hdrp", "depth-pass-factor", "0..64"), Gt("pipeline_pass_hdrp", "depth-nudge-ulps", "int -8..8"),
        }.Concat(Scene("pack")).Concat(Scene("error")).ToArray();

        /// <summary>Options of gt scripts that take a value that is not a number (Coverage: every other valued option must be in Options).</summary>
        static readonly HashSet<string> TextOptions = new HashSet<string>
        {
            "bench --device", "bench --prepare", "bench --report", "bench --plan", "bench --docs", "demo --device",
            "bench_patch_layout --ref", "bench_patch_layout --variant", "bench_patch_layout --device", "bench_patch_layout --prepare",
            "bench_patch_layout-device --device", "eval --grid", "fit-bench --dem", "lod-bench --device", "lod-bench --png",
            "lod-device --device", "query-bench --grid", "snow-bench --device", "snow-device --device",
            "shaders --only", "shaders --dxc", "shaderlab --package", "shaderlab --shaderlib", "shaderlab --check", "shaderlab --pipeline",
            "shaderlab --variants", "shaderlab --dxc", "shaderlab --counts",
        };

        /// <summary>What every probe is: out of range for most options (a probe inside an option's range is skipped for it).</summary>
        static readonly string[] Probes = { "0", "-1", "NaN", "inf", "1e30", "abc" };

        /// <summary>An option the scripts do not take, after the probe: a script that accepts the probe stops there (no work).</summary>
        const string Stopper = "--zz-not-an-option";

        static string _root, _scratch, _grid, _dem;

        [OneTimeSetUp]
        public void Prepare()
        {
            _root = HarnessRun.PackageRoot();
            _scratch = Path.Combine(_root, ".build", "rig-options");
            if (Directory.Exists(_scratch)) Directory.Delete(_scratch, true);
            Directory.CreateDirectory(_scratch);
            _grid = Path.Combine(_scratch, "grid.json");
            File.WriteAllText(_grid, PatchGridJson.Write(PatchGrid.CreateFlat(2, 2)));
            _dem = Path.Combine(_root, "Tools~", "RigTests", "Data", "dem", "N48E009_east.hgt");
        }

        public sealed class Probe
        {
            public Option Option;
            public string Value;        // null: the value left out
            public string Mention;      // the part of the message that names the value
            public override string ToString() => Option + " " + (Value ?? "(no value)");
        }

        public static IEnumerable<TestCaseData> Cases()
        {
            foreach (Option o in Options)
            {
                var values = new List<(string value, string mention)>();
                for (int k = 0; k < o.Parts.Length; k++)
                {
                    Part p = o.Parts[k];
                    // The first number gets every probe; the others of a multi-number option an absurd one and a non-number.
                    foreach (string v in k == 0 ? Probes : new[] { "1e30", "abc" })
                    {
                        if (double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) && p.Holds(d)) continue;
                        if (o.Parts.Length == 1) values.Add((v, v));
                        else
                        {
                            string[] parts = o.Valid.Split(o.Separator);
                            parts[k] = v;
                            values.Add((string.Join(o.Separator.ToString(), parts), v));
                        }
                    }
                }
                if (o.List) values.Add((o.Valid + ",abc", "abc"));
                values.Add((null, "needs a value"));
                foreach (var (value, mention) in values)
                {
                    var probe = new Probe { Option = o, Value = value, Mention = mention };
                    yield return new TestCaseData(probe).SetArgDisplayNames(probe.ToString());
                }
            }
        }

        [TestCaseSource(nameof(Cases))]
        public void RefusesOutOfRange(Probe probe)
        {
            Option o = probe.Option;
            string dir = Path.Combine(_scratch, Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            var args = new List<string>(Prefix(o, dir)) { "--" + o.Name };
            if (probe.Value != null) args.Add(probe.Value);
            if (o.Tool == "gt" && probe.Value != null) args.Add(Stopper);
            var r = Run(o, args, dir);
            TestContext.Out.WriteLine($"exit {r.Exit} in {r.Seconds:F2} s: {r.Error.Trim()}");
            Assert.Multiple(() =>
            {
                Assert.That(r.Error, Does.Not.Contain("internal error").And.Not.Contain("   at ").And.Not.Contain("Traceback"), "a crash, not a refusal");
                Assert.That(r.Exit, Is.EqualTo(2), "exit code of a bad command line");
                Assert.That(r.Error, Does.Contain("--" + o.Name), "the message names the option");
                Assert.That(r.Error, Does.Contain(probe.Mention), "the message names the value");
                Assert.That(r.Error, Does.Contain(RangeOf(o, probe)), "the message gives the accepted range");
                Assert.That(Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories).ToArray(), Is.Empty, "nothing written");
                Assert.That(r.Seconds, Is.LessThan(5.0), "refused before any work");
            });
        }

        /// <summary>The range the message must print: that of the number the probe replaced.</summary>
        static string RangeOf(Option o, Probe probe)
        {
            if (o.Parts.Length == 1 || probe.Value == null) return o.Parts.Length == 1 ? o.Parts[0].Text : "";
            string[] parts = probe.Value.Split(o.Separator);
            string[] valid = o.Valid.Split(o.Separator);
            for (int k = 0; k < parts.Length; k++)
                if (parts[k] != valid[k]) return o.Parts[k].Text;
            return "";
        }

        [Test]
        public void UnknownOptionIsRefused([Values("demo-grid", "eval", "error", "bench-plan", "lod-scene", "snow-scene", "pack", "estimate",
            "fit-bench", "fit-reference", "query-bench", "lod-cpu-bench", "lod-cache-churn", "sculpt-bench", "jitter", "gt demo", "gt bench_patch_layout", "gt fit-bench",
            "gt lod-carry", "gt snow-carry", "gt lod-device", "gt snow-device", "gt bench_patch_layout-device", "gt shaders", "gt shaderlab")] string command)
        {
            bool gt = command.StartsWith("gt ");
            var o = new Option { Tool = gt ? "gt" : "gt-cli", Command = gt ? command.Substring(3) : command, Name = "no-such-option" };
            string dir = Path.Combine(_scratch, Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            var args = new List<string>(Prefix(o, dir)) { "--no-such-option", "1" };
            var r = Run(o, args, dir);
            TestContext.Out.WriteLine($"exit {r.Exit}: {r.Error.Trim()}");
            Assert.That(r.Exit, Is.EqualTo(2), r.Error);
            Assert.That(r.Error, Does.Contain("--no-such-option"));
            Assert.That(Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories).ToArray(), Is.Empty, "nothing written");
        }

        /// <summary>
        /// The list is complete: gt-cli's numeric options (gt-cli help CMD prints each with its range)
        /// are exactly the list's gt-cli options; every option the sources read as a number is declared
        /// with a range; every valued option of a gt script is checked (check_number) and listed, or
        /// is a text option; every python option that converts its value is an options.add_number one, listed.
        /// </summary>
        [Test]
        public void Coverage()
        {
            var problems = new List<string>();
            var listed = new HashSet<string>(Options.Select(o => $"{o.Tool} {o.Command} --{o.Name}"));

            // gt-cli: what each command declares, against the list; and every numeric read in the sources declared.
            var declared = new HashSet<string>();
            foreach (string cmd in Options.Where(o => o.Tool == "gt-cli").Select(o => o.Command).Distinct()
                         .Concat(new[] { "check", "unity-asset", "bench-report", "bench-docs" }))
            {
                var r = Run(new Option { Tool = "gt-cli", Command = "help" }, new List<string> { cmd }, _scratch);
                if (r.Exit != 0) { problems.Add($"gt-cli help {cmd}: exit {r.Exit}: {r.Error.Trim()}"); continue; }
                foreach (Match m in Regex.Matches(r.Output, @"^  --([a-z0-9-]+) .*\(.*\.\..*\)$", RegexOptions.Multiline))
                    declared.Add($"gt-cli {cmd} --{m.Groups[1].Value}");
            }
            foreach (string d in declared) if (!listed.Contains(d)) problems.Add($"{d}: declared numeric but not in RigOptionTests.Options");
            foreach (string l in listed.Where(l => l.StartsWith("gt-cli ")))
                if (!declared.Contains(l)) problems.Add($"{l}: listed but gt-cli help does not give its range");
            var declaredNames = new HashSet<string>(declared.Select(d => d.Substring(d.LastIndexOf("--", StringComparison.Ordinal) + 2)));
            foreach (string file in Directory.GetFiles(Path.Combine(_root, "Tools~", "dotnet", "Gt"), "*.cs"))
                foreach (Match m in Regex.Matches(File.ReadAllText(file), @"\b[a-z]\.(?:Int|Double|Doubles|Ints)\(""([a-z0-9-]+)"""))
                    if (!declaredNames.Contains(m.Groups[1].Value))
                        problems.Add($"{Path.GetFileName(file)} reads --{m.Groups[1].Value} as a number; no command declares it with a range");

            // gt scripts: every case arm "--name)" that takes $2 is range-checked and listed, or a text option.
            foreach (string file in Directory.GetFiles(Path.Combine(_root, "Tools~", "rig"), "*.sh"))
            {
                string cmd = Path.GetFileNameWithoutExtension(file);
                foreach (Match m in Regex.Matches(File.ReadAllText(file), @"^\s*(?<names>-[a-z-]+(?:\|-[a-z-]+)*)\)(?<body>[^\n]*)$", RegexOptions.Multiline))
                {
                    string body = m.Groups["body"].Value;
                    if (!body.Contains("$2") && !body.Contains("${2")) continue;
                    string name = m.Groups["names"].Value.Split('|').Last();
                    string key = $"gt {cmd} {name}";
                    bool isText = TextOptions.Contains($"{cmd} {name}");
                    if (listed.Contains(key) && !body.Contains("check_number")) problems.Add($"{key}: listed but its case arm does not call check_number");
                    if (!listed.Contains(key) && !isText) problems.Add($"{key}: takes a value but is neither in Options (numeric) nor in TextOptions");
                }
            }
            // python: no add_argument converts a type itself; every options.add_number option is listed.
            foreach (string file in Directory.GetFiles(Path.Combine(_root, "Tools~", "rig"), "*.py"))
            {
                string cmd = Path.GetFileNameWithoutExtension(file), text = File.ReadAllText(file);
                if (cmd == "options") continue;   // the check itself
                foreach (Match m in Regex.Matches(text, @"add_argument\([^\n]*\btype=(?<type>[\w.]+)"))
                    problems.Add($"{Path.GetFileName(file)}: an option with type={m.Groups["type"].Value}: a number goes through options.add_number");
                foreach (Match m in Regex.Matches(text, @"options\.add_number\([^\n]*?""(?<name>--[a-z-]+)"""))
                    if (!listed.Contains($"gt {cmd} {m.Groups["name"].Value}")) problems.Add($"gt {cmd} {m.Groups["name"].Value}: a numeric python option not in Options");
            }
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        /// <summary>The arguments a command needs before the probed option, so that a value it accepted would reach the work.</summary>
        static IEnumerable<string> Prefix(Option o, string dir)
        {
            string out_ = Path.Combine(dir, "out");
            var baseArgs = new Dictionary<string, string[]>
            {
                ["pack"] = new[] { "--grid", _grid, "--out", out_ },
                ["error"] = new[] { "--grid", _grid, "--factor", "2", "--tiles", "2" },
                ["eval"] = new[] { "--grid", _grid, "--points", "0.5,0.5" },
                ["demo-grid"] = new[] { "--out", Path.Combine(out_, "demo.json"), "--samples", "33" },
                ["bench-plan"] = new[] { "--grid", _grid, "--out", out_, "--frames", "1" },
                ["lod-scene"] = new[] { "--out", out_, "--grid", _grid },
                ["snow-scene"] = new[] { "--out", out_, "--grid", _grid, "--resolutions", "64", "--steps", "1" },
                ["estimate"] = new[] { "--grid", _grid, "--repeat", "1", "--tiles", "2" },
                ["fit-bench"] = new[] { "--size", "33", "--patches", "2" },
                ["fit-reference"] = new[] { "--dem", _dem, "--patches", "2", "--crop", "33" },
                ["query-bench"] = new[] { "--grid", _grid, "--seconds", "0.01", "--threads", "1" },
                ["lod-cpu-bench"] = new[] { "--frames", "1", "--rounds", "1" },
                ["lod-cache-churn"] = new[] { "--frames", "1" },
                ["sculpt-bench"] = new[] { "--patches", "2", "--dabs", "1" },
                ["jitter"] = new[] { "--widths", "0.5", "--tiles", "1", "--factor", "1" },
            };
            if (o.Tool == "gt")
            {
                // Scripts that take a folder first: a fresh one (DEST must not be made; a RUN_DIR exists).
                if (o.Command == "lod-carry" || o.Command == "snow-carry") return new[] { out_ };
                if (o.Command.EndsWith("-device")) { string run = Path.Combine(_scratch, "run-dir"); Directory.CreateDirectory(run); return new[] { run }; }
                return new string[0];
            }
            if (!baseArgs.TryGetValue(o.Command, out string[] b)) return new string[0];
            var r = new List<string>();
            for (int i = 0; i < b.Length; i += 2)
                if (b[i] != "--" + o.Name) { r.Add(b[i]); r.Add(b[i + 1]); }
            if (o.Command == "bench-plan") r.Add("--quick");
            return r;
        }

        sealed class Result { public int Exit; public string Output, Error; public double Seconds; }

        /// <summary>gt-cli CMD ARGS, or bash Tools~/gt CMD ARGS with its build folder in DIR (so anything a script writes shows there).</summary>
        static Result Run(Option o, List<string> args, string dir)
        {
            ProcessStartInfo psi;
            if (o.Tool == "gt-cli") psi = new ProcessStartInfo(ReadbackRun.Cli());
            else
            {
                psi = new ProcessStartInfo("bash");
                psi.ArgumentList.Add(Path.Combine(_root, "Tools~", "gt"));
                psi.Environment["GT_BUILD_DIR"] = Path.Combine(dir, "build");
            }
            psi.ArgumentList.Add(o.Command);
            foreach (string a in args) psi.ArgumentList.Add(a);
            psi.RedirectStandardOutput = psi.RedirectStandardError = true;
            psi.UseShellExecute = false;
            var watch = Stopwatch.StartNew();
            using (var p = Process.Start(psi))
            {
                var err = p.StandardError.ReadToEndAsync();
                var output = p.StandardOutput.ReadToEndAsync();
                if (!p.WaitForExit(60000)) { p.Kill(true); return new Result { Exit = -1, Output = "", Error = "still running after 60 s (the value was accepted)", Seconds = 60 }; }
                p.WaitForExit();
                return new Result { Exit = p.ExitCode, Output = output.Result, Error = err.Result, Seconds = watch.Elapsed.TotalSeconds };
            }
        }
    }
}
