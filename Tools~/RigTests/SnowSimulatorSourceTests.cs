using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The Snow Simulator's serialized settings, which the Inspector writes directly (in Play Mode too),
    /// are read only where they are validated: an edit is checked in OnValidate (the error names field
    /// and value), and applied by Update (new buffers for a new resolution); the kernels and buffers read
    /// the settings last applied. Before, a new resolution in the Inspector reached the kernels' group
    /// counts while the buffers kept the old size, which the kernels then indexed past. Only Unity runs
    /// OnValidate; this reads the C#.
    /// </summary>
    [TestFixture]
    public class SnowSimulatorSourceTests
    {
        static string Code() => Regex.Replace(File.ReadAllText(PackageRoot.Combine("Runtime", "SnowSimulator.cs")), @"//[^\n]*", "");

        /// <summary>Problems: methods reading the serialized <c>settings.</c> without validating, a missing OnValidate, an edit Update never applies.</summary>
        internal static List<string> UnvalidatedSettingsUses(string code)
        {
            var problems = new List<string>();
            foreach (Match m in Regex.Matches(code, @"\b(?:void|bool|GraphicsBuffer|Vector4|float|int)\s+(\w+)\s*\([^)]*\)\s*\{|\b(\w+)\s*=>"))
            {
                string name = m.Groups[1].Success ? m.Groups[1].Value : m.Groups[2].Value;
                string body = m.Groups[1].Success ? RendererStateSourceTests.Body(code.Substring(m.Index), name) ?? "" : code.Substring(m.Index, code.IndexOf(';', m.Index) - m.Index);
                if (Regex.IsMatch(body, @"(?<![\w.])settings\s*\.\s*(?!Validate\s*\()\w+") && !body.Contains(".Validate("))
                    problems.Add($"{name} reads the serialized settings unvalidated");
            }
            string onValidate = RendererStateSourceTests.Body(code, "OnValidate");
            if (onValidate == null || !onValidate.Contains("Validate(")) { problems.Add("no OnValidate that validates the settings"); return problems; }
            var flags = Regex.Matches(onValidate, @"\b(_\w+)\s*=(?!=)").Select(f => f.Groups[1].Value);
            string update = RendererStateSourceTests.Body(code, "Update") ?? "";
            if (!flags.Any(f => update.Contains(f))) problems.Add("Update applies no edit OnValidate marks");
            return problems.Distinct().ToList();
        }

        [Test]
        public void InspectorEditsAreValidatedAndApplied()
        {
            Assert.That(UnvalidatedSettingsUses(Code()), Is.Empty);
        }

        /// <summary>
        /// While the compute cache's records hold the snow map's version (VertexCachePass compares it)
        /// and every simulation step bumps it, the cache evaluates every tile again every frame it
        /// snows: the manual must say so where it gives the cache's and the snow's cost.
        /// </summary>
        [Test]
        public void TheManualSaysTheCacheReEvaluatesEveryFrameWhileItSnows()
        {
            string pass = File.ReadAllText(PackageRoot.Combine("Runtime", "VertexCachePass.cs"));
            string step = RendererStateSourceTests.Body(Code(), "StepSimulation");
            Assert.That(pass, Does.Match(@"snowVersion\s*!=\s*_last\.snowVersion"), "the records are forgotten on a new snow version");
            Assert.That(step, Does.Contain("DepthVersion++"), "every step bumps the version");
            foreach (string doc in new[] { "snow.md", "performance.md" })
                Assert.That(File.ReadAllText(PackageRoot.Combine("Documentation~", doc)), Does.Contain("every tile every frame"),
                    $"{doc} says the compute cache re-evaluates every tile every frame while it snows");
        }

        [Test]
        public void SettingsCheckRejectsTheUnvalidatedReads()
        {
            string old = "void Update() { if (_depth == null) return; StepSimulation(dt); }\n" +
                         "public void StepSimulation(float dt) { settings.Params(dt); int groups = settings.resolution / 8; }\n" +
                         "public Vector4 MapSize => new Vector4(settings.resolution, 1f / settings.resolution, settings.depthCap, 0f);\n" +
                         "void OnEnable() { try { settings.Validate(); } catch (ArgumentException e) { } }";
            Assert.That(UnvalidatedSettingsUses(old), Is.EqualTo(new[]
            {
                "StepSimulation reads the serialized settings unvalidated", "MapSize reads the serialized settings unvalidated", "no OnValidate that validates the settings",
            }));
        }
    }
}
