using System;
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Running compute kernels on lavapipe with gt-compute (Tools~/computerig) and the tools around
    /// them (raw float files: ReadbackRun). A missing tool fails the test that needs it.
    /// </summary>
    static class ComputeRunner
    {
        internal static string Runner()
        {
            string build = Environment.GetEnvironmentVariable("GT_BUILD_DIR");
            if (string.IsNullOrEmpty(build)) build = PackageRoot.Combine(".build");
            string path = Path.Combine(build, "computerig", "gt-compute");
            if (!File.Exists(path)) Assert.Fail("gt-compute is missing at " + path + " (run Tools~/gt setup)");
            return path;
        }

        /// <summary>Runs a tool; a missing tool or a non-zero exit fails the test with its output.</summary>
        internal static string Run(string file, params string[] args)
        {
            var psi = new ProcessStartInfo(file) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in args) psi.ArgumentList.Add(a);
            Process p;
            try { p = Process.Start(psi); }
            catch (Exception e) { Assert.Fail($"cannot run {file}: {e.Message} (run Tools~/gt setup)"); return null; }
            using (p)
            {
                var stderr = p.StandardError.ReadToEndAsync();
                string stdout = p.StandardOutput.ReadToEnd();
                if (!p.WaitForExit(300_000)) { p.Kill(); Assert.Fail(file + " timed out"); }
                p.WaitForExit();
                if (p.ExitCode != 0)
                    Assert.Fail($"{file} {string.Join(" ", args)} exited {p.ExitCode}:\n{stdout}\n{stderr.Result}");
                return stdout;
            }
        }
    }
}
