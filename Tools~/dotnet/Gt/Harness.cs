using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>Runs gt-harness (Tools~/harness) and parses its "KEY SUB VALUE..." lines.</summary>
    sealed class Harness
    {
        public string Executable;
        public string SpirvDir;      // $BUILD_DIR/spirv: one folder per variant
        public string Device;        // --device SUBSTR, or null for the first device
        /// <summary>The drawn pass's render state as harness options (a pass_state_*.args file of
        /// Tools~/rig/render_state.py), given before every run's own options.</summary>
        public string[] PassState = Array.Empty<string>();

        /// <summary>The options of a pass_state_*.args file (one line of render_state.py).</summary>
        public static string[] ReadPassState(string file) =>
            File.ReadAllText(file).Split((char[])null, StringSplitOptions.RemoveEmptyEntries);

        /// <summary>The four tessellated stages of a variant (Tools~/rig/README.md, "Rig-only entry points and compiled files").</summary>
        public List<string> TessellatedStages(string variant)
        {
            var a = new List<string>();
            foreach (var (opt, stage) in new[] { ("--vert", "vert"), ("--tesc", "tesc"), ("--tese", "tese"), ("--frag", "frag") })
            {
                string f = Path.Combine(SpirvDir, variant, stage + ".spv");
                if (!File.Exists(f)) throw new IOException($"{f} is missing (compile it: gt shaders --only {variant})");
                a.Add(opt); a.Add(f);
            }
            if (Device != null) { a.Add("--device"); a.Add(Device); }
            return a;
        }

        /// <summary>Runs the harness; throws with its output when it fails.</summary>
        public string Run(IEnumerable<string> args)
        {
            if (!File.Exists(Executable)) throw new IOException($"{Executable} is missing (run: gt setup)");
            var psi = new ProcessStartInfo(Executable) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in PassState) psi.ArgumentList.Add(a);
            foreach (string a in args) psi.ArgumentList.Add(a);
            using var p = Process.Start(psi);
            var err = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            if (p.ExitCode != 0)
                throw new IOException($"gt-harness exited with {p.ExitCode}: {err.Result.Trim()}\n{stdout}");
            return stdout;
        }

        /// <summary>The first value after "key sub" in harness output, or null.</summary>
        public static string Value(string output, string key, string sub)
        {
            foreach (string line in output.Split('\n'))
            {
                string[] w = line.Trim().Split(' ', StringSplitOptions.RemoveEmptyEntries);
                if (w.Length >= 3 && w[0] == key && w[1] == sub) return w[2];
            }
            return null;
        }

        public static long Long(string output, string key, string sub) =>
            long.Parse(Value(output, key, sub) ?? throw new IOException($"harness printed no '{key} {sub}' line"), CultureInfo.InvariantCulture);
    }
}
