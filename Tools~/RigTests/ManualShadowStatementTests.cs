using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The manual's statements on shadows and the finest Horizon level against the code they describe,
    /// read as text: what the code does is found in it first (so a test fails if the code changes
    /// too), then the manual must say that and not the opposite.
    /// </summary>
    [TestFixture]
    public class ManualShadowStatementTests
    {
        static string Read(params string[] parts) => File.ReadAllText(PackageRoot.Combine(parts));

        static string ManualRow(string manual, string start) =>
            manual.Split('\n').Single(l => l.StartsWith(start, System.StringComparison.Ordinal));

        /// <summary>URP's shadow caster moves each vertex along its normal (URP's ApplyShadowBias with the
        /// vertex normal, as URP's own ShadowCasterPass): the manual and internals.md say so.</summary>
        [Test]
        public void UrpShadowsHaveTheNormalBiasTheAdapterApplies()
        {
            string adapter = Read("Shaders", "Pipelines", "URPAdapter.hlsl");
            Assert.That(Regex.IsMatch(adapter, @"#define\s+GT_SHADOW_CASTER_NORMAL_BIAS\b"), Is.True, "the URP adapter's shadow caster has a normal bias");
            Assert.That(Regex.IsMatch(adapter, @"GT_ObjectToShadowClip\(float3 positionOS, float3 normalWS\)[^}]*ApplyShadowBias\(positionWS, normalWS,"), Is.True,
                "through URP's ApplyShadowBias with the vertex normal");
            string manual = Read("Documentation~", "index.md"), internals = Read("Documentation~", "internals.md");
            string urp = ManualRow(manual, "| URP 14 |");
            Assert.That(urp, Does.Contain("normal bias").And.Not.Contain("no normal bias"), "index.md, Pipelines, URP row");
            Assert.That(internals, Does.Not.Contain("no normal bias"), "internals.md, Shadow bias");
        }

        /// <summary>The finest Horizon level is at least 16 m of the terrain's width in world units, which
        /// the renderer takes from its world frame: Terrain Size x times the Transform's x scale.</summary>
        [Test]
        public void TheFinestLevelFollowsTerrainSize()
        {
            string levels = Read("Runtime", "GregoryTerrainRenderer.cs");
            string frame = Read("Runtime", "Core", "Terrain", "TerrainWorldFrame.cs");
            Assert.That(levels, Does.Contain("double metres = WorldUnitsPerObjectUnit.x;"), "the levels' width in metres");
            Assert.That(frame, Does.Match(@"ObjectScale => new Double3\(terrainSize\.x \* Length\(localToWorld\.c0\)"),
                "world units per object unit: Terrain Size x times the Transform's x axis");
            string row = ManualRow(Read("Documentation~", "index.md"), "| Tessellation | Horizon levels |");
            Assert.That(row, Does.Contain("Terrain Size").And.Not.Contain("from the Transform's x scale in metres per terrain unit"),
                "index.md, Horizon levels: what the finest level's width follows");
        }

        /// <summary>The manual's shadow-casting row says what TessellationViewTests checks on the compiled
        /// passes: the shadow maps tessellate with the drawing camera's factors, culled in the light's view.</summary>
        [Test]
        public void TheManualSaysShadowsTessellateAsTheCamera()
        {
            string row = ManualRow(Read("Documentation~", "index.md"), "| Lighting | Shadow casting |");
            Assert.That(row, Does.Contain("that camera's factors").And.Contain("cull it in the light's view"), "index.md, Shadow casting");
        }
    }
}
