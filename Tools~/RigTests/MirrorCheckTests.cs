using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// gt mirror (<see cref="MirrorCheck"/>): every HLSL function of the mirrored folders has its Core
    /// twin with the same parameter shapes and keyword switches, or an allow-list entry with a reason.
    /// The broken-input tests run the check on a temp copy of Shaders/ with one function renamed, one
    /// parameter added, one keyword read added, and show it fails naming the file and the function.
    /// </summary>
    [TestFixture]
    public class MirrorCheckTests
    {
        static string AllowList => PackageRoot.Combine(MirrorCheck.AllowListPath);

        static MirrorCheck.Report CheckCopy(Func<string, string> edit, string file)
        {
            string root = Path.Combine(Path.GetTempPath(), "gt-mirror-" + Guid.NewGuid().ToString("N"));
            try
            {
                foreach (string folder in MirrorCheck.Folders)
                {
                    string from = PackageRoot.Combine("Shaders", folder), to = Path.Combine(root, "Shaders", folder);
                    Directory.CreateDirectory(to);
                    foreach (string f in Directory.GetFiles(from, "*.hlsl")) File.Copy(f, Path.Combine(to, Path.GetFileName(f)));
                }
                string path = Path.Combine(root, "Shaders", file);
                string before = File.Exists(path) ? File.ReadAllText(path) : "";
                string after = edit(before);
                Assert.That(after, Is.Not.EqualTo(before), $"the edit changed {file}");
                File.WriteAllText(path, after);
                return MirrorCheck.Check(root, typeof(TerrainParams).Assembly, AllowList);
            }
            finally { if (Directory.Exists(root)) Directory.Delete(root, true); }
        }

        static string Failures(MirrorCheck.Report r) => string.Join("\n", r.Failures);

        [Test]
        public void EveryHlslFunctionHasItsTwinOrAReason()
        {
            MirrorCheck.Report r = MirrorCheck.Check(PackageRoot.Path, typeof(TerrainParams).Assembly, AllowList);
            TestContext.Progress.WriteLine(MirrorCheck.Summary(r));
            Assert.That(r.Pairs, Has.Count.GreaterThanOrEqualTo(20), "the twin files found (Library, Terrain, Cache, Snow, Grid)");
            Assert.That(r.Matched, Is.GreaterThan(150), "functions paired by name");
            Assert.That(r.Failures.Select(f => f.ToString()), Is.Empty, "a mirror mismatch: fix it, or add it to Tools~/rig/mirror-allow.txt with its reason");
            Assert.That(r.Stale.Select(e => $"line {e.Line}: {e.Kind} {e.Stem} {e.Name}"), Is.Empty, "allow-list entries that allow nothing now: remove them");
        }

        [Test]
        public void ARenamedFunctionFailsOnBothSides()
        {
            MirrorCheck.Report r = CheckCopy(s => s.Replace("float3 GregoryNormal(", "float3 GregoryNormalOf("), "Library/GregoryEval.hlsl");
            TestContext.Progress.WriteLine(Failures(r));
            Assert.That(r.Failures.Any(f => f.Kind == "hlsl-only" && f.Name == "GregoryNormalOf" && f.Message.Contains("Shaders/Library/GregoryEval.hlsl")), Failures(r));
            Assert.That(r.Failures.Any(f => f.Kind == "cs-only" && f.Name == "Normal" && f.Message.Contains("Runtime/Core/Library/GregoryEval.cs")), Failures(r));
        }

        [Test]
        public void AnExtraParameterFails()
        {
            MirrorCheck.Report r = CheckCopy(s => s.Replace("void GregoryBasisBernstein(float t,", "void GregoryBasisBernstein(float t, float scale,"), "Library/GregoryBasis.hlsl");
            TestContext.Progress.WriteLine(Failures(r));
            Assert.That(r.Failures.Any(f => f.Kind == "shape" && f.Name == "GregoryBasisBernstein" && f.Message.StartsWith("4 parameters in HLSL, 3 in C#")
                && f.Message.Contains("Shaders/Library/GregoryBasis.hlsl:")), Failures(r));
        }

        [Test]
        public void AnInParameterThatBecameInoutFails()
        {
            MirrorCheck.Report r = CheckCopy(s => s.Replace("float3 GregoryNormalFromDerivatives(float3 dPdu,", "float3 GregoryNormalFromDerivatives(inout float3 dPdu,"), "Library/GregoryEval.hlsl");
            TestContext.Progress.WriteLine(Failures(r));
            Assert.That(r.Failures.Any(f => f.Kind == "shape" && f.Name == "GregoryNormalFromDerivatives" && f.Message.Contains("parameter 1 is 'inout float3 dPdu' in HLSL, 'Float3 dPdu' in C#")), Failures(r));
        }

        [Test]
        public void AKeywordReadWithoutTerrainKeywordsFails()
        {
            MirrorCheck.Report r = CheckCopy(s => s.Replace("float3 GregoryNormalFromDerivatives(float3 dPdu, float3 dPdv)\n{", "float3 GregoryNormalFromDerivatives(float3 dPdu, float3 dPdv)\n{\n#if defined(GT_SNOW)\n#endif"), "Library/GregoryEval.hlsl");
            TestContext.Progress.WriteLine(Failures(r));
            Assert.That(r.Failures.Any(f => f.Kind == "keyword" && f.Name == "GregoryNormalFromDerivatives" && f.Message.Contains("GT_SNOW")), Failures(r));
        }

        [Test]
        public void AnHlslFileWithoutTwinFails()
        {
            MirrorCheck.Report r = CheckCopy(_ => "float MirrorProbe(float x) { return x; }\n", "Library/MirrorProbe.hlsl");
            Assert.That(r.Failures.Any(f => f.Kind == "hlsl-file" && f.Stem == "Library/MirrorProbe" && f.Message.Contains("Runtime/Core/Library/MirrorProbe.cs")), Failures(r));
        }

        [Test]
        public void AnEntryThatAllowsNothingIsStale()
        {
            string list = Path.Combine(Path.GetTempPath(), "gt-mirror-allow-" + Guid.NewGuid().ToString("N") + ".txt");
            try
            {
                File.WriteAllText(list, File.ReadAllText(AllowList) + "cs-only Library/GregoryEval NoSuchFunction -- an entry for a function that is not there\n");
                MirrorCheck.Report r = MirrorCheck.Check(PackageRoot.Path, typeof(TerrainParams).Assembly, list);
                Assert.That(r.Stale.Select(e => e.Name), Is.EqualTo(new[] { "NoSuchFunction" }));
                Assert.That(r.Passed, Is.False);
                File.WriteAllText(list, "cs-only Library/GregoryEval Normal\n");
                var e = Assert.Throws<FormatException>(() => MirrorCheck.ReadAllowList(list));
                Assert.That(e.Message, Does.Contain(":1:").And.Contain("KIND STEM NAME -- REASON"));
            }
            finally { File.Delete(list); }
        }
    }
}
