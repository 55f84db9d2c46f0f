using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Static checks over the Unity-side C# (Runtime/*.cs) for what only a Unity editor could show
    /// running: the material asset is never written (per-renderer keywords go on the runtime copy),
    /// the renderer draws per camera from the pipelines' callbacks, and every callback it registers is
    /// removed again. The Unity-side tests (Tests/Runtime, Tests/Editor) check the same behaviour in
    /// Unity; these keep it from regressing where no editor runs. Each check is also run on a broken
    /// input, which it must reject.
    /// </summary>
    [TestFixture]
    public class UnityBehaviourSourceTests
    {
        /// <summary>Material members that change a material (and so a .mat asset when called on one).</summary>
        static readonly string[] MaterialWriters =
        {
            "EnableKeyword", "DisableKeyword", "SetKeyword", "SetBuffer", "SetConstantBuffer", "SetVector",
            "SetVectorArray", "SetMatrix", "SetMatrixArray", "SetFloat", "SetFloatArray", "SetInt", "SetInteger",
            "SetColor", "SetColorArray", "SetTexture", "SetTextureOffset", "SetTextureScale", "SetShaderPassEnabled",
            "SetOverrideTag", "CopyPropertiesFromMaterial",
        };
        static readonly string[] MaterialSetters = { "shaderKeywords", "enabledKeywords", "renderQueue", "shader", "globalIlluminationFlags", "enableInstancing" };

        /// <summary>The one file and the names in it that may write a material: the renderer's runtime copy.</summary>
        const string CopyFile = "DrawMaterialCopy.cs";
        static readonly string[] CopyNames = { "_drawMaterial", "copy" };

        static Dictionary<string, string> RuntimeSources() =>
            Directory.GetFiles(PackageRoot.Combine("Runtime"), "*.cs", SearchOption.TopDirectoryOnly)
                .ToDictionary(Path.GetFileName, File.ReadAllText);

        static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        /// <summary>
        /// Every place in <paramref name="files"/> (name -> C#) that writes through a Material-typed
        /// name (field, property, parameter or local declared as Material in any of the files), other
        /// than the runtime copy in <see cref="CopyFile"/>. Also any write through <c>sharedMaterial</c>.
        /// </summary>
        internal static List<string> MaterialWrites(IDictionary<string, string> files)
        {
            var code = files.ToDictionary(f => f.Key, f => StripComments(f.Value));
            var materialNames = new HashSet<string> { "sharedMaterial", "sharedMaterials" };
            foreach (string c in code.Values)
                foreach (Match m in Regex.Matches(c, @"\bMaterial(?:\[\])?\s+(\w+)\s*(?=[;,=)\{]|=>)"))
                    materialNames.Add(m.Groups[1].Value);
            string writers = string.Join("|", MaterialWriters), setters = string.Join("|", MaterialSetters);
            var found = new List<string>();
            foreach (var f in code)
            {
                var calls = Regex.Matches(f.Value, $@"\b(\w+)\s*\.\s*(?:(?:{writers})\s*\(|(?:{setters})\s*=[^=])");
                foreach (Match m in calls)
                {
                    string receiver = m.Groups[1].Value;
                    if (!materialNames.Contains(receiver)) continue;
                    if (f.Key == CopyFile && CopyNames.Contains(receiver)) continue;
                    int line = f.Value.Take(m.Index).Count(ch => ch == '\n') + 1;
                    found.Add($"{f.Key}:{line}: {m.Value.Trim()}");
                }
            }
            return found;
        }

        [Test]
        public void RuntimeCodeNeverWritesTheMaterialAsset()
        {
            var sources = RuntimeSources();
            Assert.That(sources.Keys, Does.Contain(CopyFile), "the runtime copy's file exists");
            Assert.That(MaterialWrites(sources), Is.Empty,
                "writes to a material other than the renderer's runtime copy (keywords and buffers chosen by a renderer must not reach the asset)");
        }

        [Test]
        public void MaterialWriteCheckRejectsWritesToTheAsset()
        {
            // What the package did before: keywords and buffers on the shared material asset.
            var broken = new Dictionary<string, string>
            {
                ["GregoryTerrainRenderer.cs"] = "[SerializeField] Material material;\nvoid A() { material.EnableKeyword(VertexCachePass.Keyword); }",
                ["SnowSimulator.cs"] = "[SerializeField] Material terrainMaterial;\nvoid Bind() { terrainMaterial.SetBuffer(Ids.Depth, _depth); }",
                ["Other.cs"] = "void B(Renderer r) { r.sharedMaterial.shaderKeywords = new string[0]; }",
                ["Property.cs"] = "public Material Material { get; set; }\nvoid C() { x.Material.DisableKeyword(\"GT_SNOW\"); }",
                // The copy's own name outside its file is still a write to some material.
                ["Elsewhere.cs"] = "Material _drawMaterial;\nvoid D() { _drawMaterial.SetVector(1, v); }",
            };
            var found = MaterialWrites(broken);
            Assert.That(found.Count, Is.EqualTo(5), "flagged: " + string.Join("; ", found));
            // And the copy in its own file is allowed, a comparison is no write, a property block is no material.
            var fine = new Dictionary<string, string>
            {
                [CopyFile] = "Material _drawMaterial;\nvoid E(Material copy) { _drawMaterial.CopyPropertiesFromMaterial(material); copy.EnableKeyword(k); }",
                ["Props.cs"] = "MaterialPropertyBlock _props; Material material;\nvoid F() { _props.SetVector(1, v); if (material.shader == s) {} }",
            };
            Assert.That(MaterialWrites(fine), Is.Empty);
        }

        /// <summary>
        /// Subscriptions <c>X.ev += H</c> to the events the package uses (camera callbacks, domain
        /// reload) without a matching <c>X.ev -= H</c> in the same file set.
        /// </summary>
        internal static List<string> UnbalancedSubscriptions(IDictionary<string, string> files)
        {
            string all = string.Join("\n", files.Values.Select(StripComments));
            var adds = Regex.Matches(all, @"(\w+\.\w+)\s*\+=\s*(\w+)\s*;").Select(m => (ev: m.Groups[1].Value, h: m.Groups[2].Value)).Distinct();
            var removes = new HashSet<(string, string)>(Regex.Matches(all, @"(\w+\.\w+)\s*-=\s*(\w+)\s*;").Select(m => (m.Groups[1].Value, m.Groups[2].Value)));
            return adds.Where(a => !removes.Contains(a)).Select(a => $"{a.ev} += {a.h}").ToList();
        }

        [Test]
        public void RendererDrawsPerCameraFromBothPipelinesCallbacks()
        {
            var renderer = RuntimeSources().Where(f => f.Key.StartsWith("GregoryTerrainRenderer") || f.Key == "TerrainFrameDriver.cs").ToDictionary(f => f.Key, f => f.Value);
            string code = string.Join("\n", renderer.Values.Select(StripComments));
            Assert.That(code, Does.Match(@"RenderPipelineManager\.beginCameraRendering\s*\+="), "SRP camera callback registered");
            Assert.That(code, Does.Match(@"Camera\.onPreCull\s*\+="), "Built-in camera callback registered");
            Assert.That(code, Does.Not.Match(@"void\s+(Late)?Update\s*\("), "no per-frame Update draws (Edit Mode runs Update only on changes)");
            Assert.That(code, Does.Match(@"new\s+RenderParams\s*\("), "the draw is in these files");
            Assert.That(DrawsWithoutCamera(code), Is.Empty, "every RenderParams names the camera it draws for");
            Assert.That(UnbalancedSubscriptions(RuntimeSources()), Is.Empty, "every callback registered is removed again");
        }

        /// <summary>The <c>new RenderParams(...) { ... }</c> initialisers that set no <c>camera</c>.</summary>
        internal static List<string> DrawsWithoutCamera(string code) =>
            Regex.Matches(code, @"new\s+RenderParams\s*\([^)]*\)\s*\{(?<body>[^}]*)\}")
                .Where(m => !Regex.IsMatch(m.Groups["body"].Value, @"\bcamera\s*="))
                .Select(m => m.Value).ToList();

        [Test]
        public void PerCameraChecksRejectTheOldDraw()
        {
            // The LateUpdate draw this replaced: RenderParams without a camera, drawn in every camera.
            string old = "void LateUpdate() => Draw();\nvoid Draw() { var rp = new RenderParams(material) { worldBounds = b, matProps = _props, layer = 0, }; }";
            Assert.That(DrawsWithoutCamera(old).Count, Is.EqualTo(1));
            Assert.That(DrawsWithoutCamera("var rp = new RenderParams(m) { camera = cam, layer = 0 };"), Is.Empty);
            var leaks = new Dictionary<string, string>
            {
                ["A.cs"] = "void OnEnable() { Camera.onPreCull += OnPreCull; AssemblyReloadEvents.beforeAssemblyReload += ReleaseAll; }\n" +
                           "void OnDisable() { AssemblyReloadEvents.beforeAssemblyReload -= ReleaseGpuResources; }",
            };
            Assert.That(UnbalancedSubscriptions(leaks), Is.EquivalentTo(new[] { "Camera.onPreCull += OnPreCull", "AssemblyReloadEvents.beforeAssemblyReload += ReleaseAll" }));
        }
    }
}
