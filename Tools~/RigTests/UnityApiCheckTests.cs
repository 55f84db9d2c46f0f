using System.Diagnostics;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Builds Tools~/UnityApiCheck: the package's Unity-side C# (Runtime player and editor builds,
    /// Editor, Samples~) against stubs written from Unity's Scripting Reference. Honest only as far
    /// as the stubs are faithful to the documentation (Tools~/UnityApiCheck/README.md).
    /// </summary>
    [TestFixture]
    public class UnityApiCheckTests
    {
        [Test]
        public void UnitySideCodeCompilesAgainstTheDocumentedApi()
        {
            string project = PackageRoot.Combine("Tools~", "UnityApiCheck", "UnityApiCheck.csproj");
            var psi = new ProcessStartInfo("dotnet", $"build \"{project}\" -c Release -nologo")
            {
                RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false,
            };
            psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
            psi.Environment["DOTNET_NOLOGO"] = "1";
            using var p = Process.Start(psi);
            string output = p.StandardOutput.ReadToEnd() + p.StandardError.ReadToEnd();
            p.WaitForExit();
            var standIns = output.Split('\n').Where(l => l.Contains("[unity-api] Core stand-in")).Select(l => l.Trim()).Distinct().ToList();
            TestContext.Out.WriteLine($"Core stand-ins in use: {standIns.Count}");
            foreach (var s in standIns) TestContext.Out.WriteLine("  " + s);
            Assert.That(p.ExitCode, Is.EqualTo(0), "dotnet build of UnityApiCheck failed:\n" +
                string.Join("\n", output.Split('\n').Where(l => l.Contains("error")).Distinct().Take(40)));
        }

        [Test]
        public void EveryCoreStandInIsListedInItsProject()
        {
            string dir = PackageRoot.Combine("Tools~", "UnityApiCheck");
            string csproj = File.ReadAllText(Path.Combine(dir, "CoreExpectedProject", "CoreExpected.csproj"));
            var missing = Directory.GetFiles(Path.Combine(dir, "CoreExpected"), "*.cs")
                .Select(Path.GetFileName).Where(n => !csproj.Contains("CoreExpected/" + n + "\"")).ToList();
            Assert.That(missing, Is.Empty, "not compiled by CoreExpected.csproj: " + string.Join(", ", missing));
        }
    }
}
