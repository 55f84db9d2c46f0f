using System;
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

        /// <summary>Runs a tool (ReadbackRun.Exec): a missing tool or a non-zero exit fails the test with its output.</summary>
        internal static string Run(string file, params string[] args) => ReadbackRun.Exec(file, args, null);
    }
}
