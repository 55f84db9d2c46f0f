// What keeps gt test within its time (Tools~/development.md, "Test command"): the rig's scripts call
// the python interpreter gt test resolved once, not a version manager's shim per call.
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture]
    public class TestCommandCostTests
    {
        static string Rig => PackageRoot.Combine("Tools~", "rig");

        /// <summary>bash -c SCRIPT with common.sh sourced first, and the given environment.</summary>
        static HarnessRun Bash(string script, IDictionary<string, string> env) =>
            HarnessRun.Start("bash", new[] { "-c", $"source '{Path.Combine(Rig, "common.sh")}'\n{script}" }, env);

        /// <summary>
        /// A script's python3 (check_number here, as every numeric option of a gt script) runs GT_PYTHON
        /// when it is set: a stand-in interpreter that leaves a mark and hands over to the real one.
        /// </summary>
        [Test]
        public void ScriptsCallTheResolvedPython()
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-python-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string real = HarnessRun.Start("python3", new[] { "-c", "import sys; print(sys.executable)" }).Stdout.Trim();
                Assert.That(File.Exists(real), Is.True, $"python3's sys.executable: '{real}'");
                string mark = Path.Combine(dir, "called"), standIn = Path.Combine(dir, "python");
                File.WriteAllText(standIn, $"#!/bin/sh\necho \"$@\" >> '{mark}'\nexec '{real}' \"$@\"\n");
                Assert.That(HarnessRun.Start("chmod", new[] { "+x", standIn }).ExitCode, Is.EqualTo(0));
                var env = new Dictionary<string, string> { ["GT_PYTHON"] = standIn, ["GT_BUILD_DIR"] = Path.Combine(dir, "build") };

                HarnessRun ok = Bash("check_number demo --tiles tiles 5 && echo accepted", env);
                Assert.That(ok.Stdout, Does.Contain("accepted"), ok.Stderr);
                Assert.That(File.Exists(mark) ? File.ReadAllText(mark) : "(not called)", Does.Contain("options.py demo --tiles tiles 5"),
                            "check_number ran python3 from PATH, not GT_PYTHON");

                HarnessRun refused = Bash("check_number demo --tiles tiles 0; echo unreachable", env);
                Assert.That(refused.ExitCode, Is.EqualTo(2), "a bad value still exits 2 through the resolved python");
                Assert.That(refused.Stderr, Does.Contain("gt demo: --tiles 0 is out of range (1..1024)"));
                Assert.That(refused.Stdout, Does.Not.Contain("unreachable"));
            }
            finally { Directory.Delete(dir, true); }
        }

        /// <summary>gt test resolves the interpreter and exports it before anything runs python (setup included).</summary>
        [Test]
        public void TheTestCommandExportsThePythonItResolved()
        {
            string test = File.ReadAllText(Path.Combine(Rig, "test.sh"));
            int export = test.IndexOf("export GT_PYTHON", System.StringComparison.Ordinal);
            int setup = test.IndexOf("setup.sh", System.StringComparison.Ordinal);
            Assert.That(export, Is.GreaterThanOrEqualTo(0), "test.sh exports GT_PYTHON");
            Assert.That(export, Is.LessThan(setup), "exported before setup");
            Assert.That(test, Does.Contain("resolve_python"), "resolved from python3's own sys.executable");
            string resolved = Bash("resolve_python", null).Stdout.Trim();
            Assert.That(File.Exists(resolved), Is.True, $"resolve_python printed '{resolved}'");
            Assert.That(File.ReadAllText(resolved).StartsWith("#!"), Is.False, $"{resolved} is a script (a shim), not the interpreter");
        }
    }
}
