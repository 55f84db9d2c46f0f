// The hostile-input suite's gt-cli part (issue 25): each case runs the built gt-cli (gt setup) with a
// bad command line or a bad file and asserts a clear refusal (exit 2 for bad usage, 1 for bad data;
// stderr names the option or field and the value, short, with no stack trace) or a documented
// acceptance (exit 0). Core's cases are in HostileInputTests.cs; the outcome kinds are
// HostileCase's.
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>gt-cli ended with exit 2 (bad usage); the message is its stderr.</summary>
    public sealed class CliBadUsage : Exception { public CliBadUsage(string m) : base(m) { } }
    /// <summary>gt-cli ended with exit 1 (bad data); the message is its stderr.</summary>
    public sealed class CliBadData : Exception { public CliBadData(string m) : base(m) { } }
    /// <summary>gt-cli ended any other way, or printed a stack trace: a crash.</summary>
    public sealed class CliCrash : Exception { public CliCrash(string m) : base(m) { } }

    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class HostileCliTests
    {
        const int TimeoutMs = 30000;
        static readonly HostileTally Tally = new HostileTally();
        static string _dir;

        [OneTimeTearDown]
        public void Report() => TestContext.Progress.WriteLine("hostile gt-cli cases: " + Tally);

        [TestCaseSource(nameof(Cases))]
        public void Hostile(HostileCase c) => Tally.Assert(c, TimeoutMs);

        /// <summary>Runs gt-cli; returns stdout on exit 0, throws by exit code otherwise.</summary>
        static string Cli(params string[] args)
        {
            var psi = new ProcessStartInfo(ReadbackRun.Cli()) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) psi.ArgumentList.Add(a);
            using (var p = Process.Start(psi))
            {
                var err = p.StandardError.ReadToEndAsync();
                string output = p.StandardOutput.ReadToEnd();
                if (!p.WaitForExit(2 * TimeoutMs)) { p.Kill(true); throw new CliCrash("killed after " + 2 * TimeoutMs + " ms"); }
                string error = err.Result;
                if (error.Contains("   at ") || error.Contains("Unhandled exception")) throw new CliCrash($"exit {p.ExitCode}, a stack trace: {error}");
                if (p.ExitCode == 0) return output + error;
                if (p.ExitCode == 2) throw new CliBadUsage(error);
                if (p.ExitCode == 1) throw new CliBadData(error);
                throw new CliCrash($"exit {p.ExitCode}: {error}");
            }
        }

        static HostileCase Usage(string name, string[] args, params string[] mentions) =>
            HostileCase.Refuse<CliBadUsage>("gt-cli", name + ": " + string.Join(" ", Short(args)), () => Cli(args), mentions);

        static HostileCase Data(string name, string[] args, params string[] mentions) =>
            HostileCase.Refuse<CliBadData>("gt-cli", name + ": " + string.Join(" ", Short(args)), () => Cli(args), mentions);

        static HostileCase Accept(string name, string why, string[] args, params string[] mentions)
        {
            string output = null;
            return HostileCase.Accept("gt-cli", name + ": " + string.Join(" ", Short(args)), why, () => output = Cli(args), () => output, mentions);
        }

        static string[] Short(string[] args) => Array.ConvertAll(args, a => a.Length > 40 ? a.Substring(0, 40) + "..." : a.Replace(_dir ?? "\0", "DIR"));

        static string Write(string name, string text)
        {
            string path = Path.Combine(_dir, name);
            File.WriteAllText(path, text);
            return path;
        }

        public static IEnumerable<TestCaseData> Cases()
        {
            _dir = Path.Combine(Rig.Tests.HarnessRun.PackageRoot(), ".build", "hostile-cli");
            Directory.CreateDirectory(_dir);
            PatchGrid good = PatchGrid.CreateFlat(3, 2);
            string grid = Write("good.json", PatchGridJson.Write(good));
            string big = Write("float-overflow.json", PatchGridJson.Write(good).Replace("\"patches\":[\n[[0,0,0]", "\"patches\":[\n[[0,0,1e39]"));
            PatchGrid flip = PatchGrid.CreateFlat(1, 1);
            for (int k = 0; k < 20; k++) { Double3 c = flip.Patches[0][k]; flip.Patches[0][k] = new Double3(c.y, c.x, c.z); }
            string flipped = Write("flipped.json", PatchGridJson.Write(flip));
            string empty = Write("empty.json", "");
            string garbage = Path.Combine(_dir, "garbage.json");
            var bytes = new byte[4096];
            new Random(25).NextBytes(bytes);
            File.WriteAllBytes(garbage, bytes);
            string hugeString = Write("huge-string.json", "{\"format\":\"" + new string('x', 20000000) + "\"}");
            string unknownMember = Write("unknown-member.json", PatchGridJson.Write(good).Replace("{\"format\"", "{\"colums\":3,\"format\""));
            string points = Write("points.txt", "0.5 0.5\n0.1,zz\n");
            string o = Path.Combine(_dir, "out");

            var all = new List<HostileCase>
            {
                Usage("unknown command", new[] { "pakc" }, "unknown command", "pakc"),
                Usage("argument without dashes", new[] { "check", "grid.json" }, "unexpected argument", "grid.json"),
                Usage("a lone --", new[] { "check", "--" }, "unexpected argument"),
                Usage("mistyped option", new[] { "check", "--gird", grid }, "unknown option --gird", "--grid"),
                Usage("option of another command", new[] { "check", "--grid", grid, "--tiles", "8" }, "unknown option --tiles"),
                Usage("option given twice", new[] { "check", "--grid", grid, "--grid", grid }, "--grid", "twice"),
                Usage("a 100 KB option name", new[] { "check", "--" + new string('z', 100000) }, "unknown option", "100000 characters"),
                Usage("required option missing", new[] { "check" }, "--grid", "required"),
                Usage("required value missing", new[] { "pack", "--grid", grid, "--out" , "--tiles", "4" }, "--out", "needs a value"),
                Accept("check a good grid", "exit 0 with a summary", new[] { "check", "--grid", grid }, "valid grid", "3 x 2"),
                Accept("check a flipped grid", "valid data, listed as a warning with the patch index", new[] { "check", "--grid", flipped }, "warning: patch 0 (0, 0)", "pointing down"),
                Data("a folder as the grid", new[] { "check", "--grid", _dir }, "is a folder", "expected a file"),
                Data("a missing grid", new[] { "check", "--grid", Path.Combine(_dir, "nope.json") }, "nope.json", "does not exist"),
                Data("an empty grid file", new[] { "check", "--grid", empty }, "expected an object"),
                Data("a binary grid file", new[] { "check", "--grid", garbage }, "the document", "expected an object"),
                Data("a 20 MB format string", new[] { "check", "--grid", hugeString }, "format", "20000000 characters"),
                Data("a misspelt member", new[] { "check", "--grid", unknownMember }, "colums", "not part of the format"),
                Data("a control point beyond float", new[] { "check", "--grid", big }, "slot 0", "1E+39", "float32"),
                Data("pack a grid beyond float", new[] { "pack", "--grid", big, "--out", o }, "slot 0", "1E+39"),
                Data("a folder as the points file", new[] { "eval", "--grid", grid, "--points-file", _dir }, "is a folder"),
                Usage("a bad point in the points file", new[] { "eval", "--grid", grid, "--points-file", points }, "--points-file", "0.1,zz"),
                Usage("a bad point", new[] { "eval", "--grid", grid, "--points", "0.5,0.5;0.1,zz" }, "--points", "0.1,zz"),
                Data("a point outside the square", new[] { "eval", "--grid", grid, "--points", "1.5,0.5" }, "--points", "1.5,0.5", "unit square"),
                Data("a range 1e-300 wide", new[] { "pack", "--grid", grid, "--range", "0,0,1e-300,1e-300", "--out", o }, "range width", "1E-300", "1E-10"),
                Data("a range of width 0", new[] { "pack", "--grid", grid, "--range", "0.5,0,0.5,1", "--out", o }, "range.g", "0.5"),
                Data("a mirrored range", new[] { "pack", "--grid", grid, "--range", "0.6,0,0.1,1", "--out", o }, "range.g", "0.1"),
                Usage("a range outside the square", new[] { "pack", "--grid", grid, "--range", "-5,0,1,1", "--out", o }, "--range", "c -5", "0..1"),
                Usage("tiles 0", new[] { "pack", "--grid", grid, "--tiles", "0", "--out", o }, "--tiles 0", "1..1024"),
                Usage("tiles 1000000000", new[] { "pack", "--grid", grid, "--tiles", "1000000000", "--out", o }, "--tiles 1000000000", "1..1024"),
                Usage("max factor 65", new[] { "pack", "--grid", grid, "--max-factor", "65", "--out", o }, "--max-factor 65", "1..64"),
                Usage("octaves 1000", new[] { "pack", "--grid", grid, "--octaves", "1000", "--out", o }, "--octaves 1000", "0..16"),
                Usage("gamma 0", new[] { "pack", "--grid", grid, "--gamma", "0", "--out", o }, "--gamma 0", "not 0"),
                Usage("orbit of 0 frames", new[] { "pack", "--grid", grid, "--orbit", "0,10", "--out", o }, "--orbit", "frames 0", "1..100000"),
                Accept("pack a good scene", "the control: exit 0", new[] { "pack", "--grid", grid, "--out", o }, "packed 3x2"),
            };
            foreach (string bad in new[] { "1x", "", "1.5", "1e3", "99999999999", "0x10", "ten", "+-1" })
                all.Add(Usage($"tiles '{bad}'", new[] { "pack", "--grid", grid, "--tiles", bad, "--out", o }, "--tiles", bad.Length == 0 ? "needs a value" : bad, "1..1024"));
            foreach (string bad in new[] { "nan", "NaN", "inf", "-Infinity", "1e400", "abc", "1,5", "0x1p3", "--" })
                all.Add(bad == "--"
                    ? Usage("gamma with no value", new[] { "pack", "--grid", grid, "--gamma", "--out", o }, "--gamma")
                    : Usage($"gamma '{bad}'", new[] { "pack", "--grid", grid, "--gamma", bad, "--out", o }, "--gamma", bad));
            foreach (string bad in new[] { "0,0,1", "0,0,1,1,1", "0,0,x,1", "0,0,nan,1", "0,0,1e999,1", "0;0;1;1", "" })
                all.Add(Usage($"range '{bad}'", new[] { "pack", "--grid", grid, "--range", bad, "--out", o }, "--range"));
            foreach (string bad in new[] { "0.01,16,2", "0.01,16,2,x", "0.01,inf,2,2" })
                all.Add(Usage($"noise '{bad}'", new[] { "pack", "--grid", grid, "--noise", bad, "--out", o }, "--noise"));
            foreach (string s in new[] { "2000000000", "-5", "1" })
                all.Add(Usage($"demo-grid samples {s}", new[] { "demo-grid", "--samples", s, "--out", Path.Combine(_dir, "demo.json") }, "--samples", s));
            all.Add(Usage("demo-grid 100000 x 100000 patches", new[] { "demo-grid", "--columns", "100000", "--rows", "100000", "--out", Path.Combine(_dir, "demo.json") }, "--columns 100000", "1..1024"));
            all.Add(Usage("jitter width 'x'", new[] { "jitter", "--widths", "1e-2,x" }, "--widths", "x is not a number"));
            all.Add(Data("jitter width 1e-300", new[] { "jitter", "--widths", "1e-300" }, "width", "1E-300"));
            foreach (string w in new[] { "0", "2" })
                all.Add(Usage($"jitter width {w}", new[] { "jitter", "--widths", w }, "--widths", w + " is out of range", ">0..1"));
            foreach (string cmd in new[] { "eval", "pack", "estimate", "jitter", "unity-asset", "error", "bench-plan", "bench-report", "snow-scene", "demo-grid" })
                all.Add(Usage($"{cmd} with a mistyped option", new[] { cmd, "--no-such-option", "1" }, "unknown option --no-such-option"));
            for (int k = 0; k < all.Count; k++)
                yield return new TestCaseData(all[k]).SetArgDisplayNames(k.ToString("D3", CultureInfo.InvariantCulture) + " " + all[k].Name);
        }
    }
}
