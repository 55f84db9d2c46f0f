using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using static GregoryTerrain.Rig.Tests.EditorToolSourceTests;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Source-level checks of issue 40's first hour where only a Unity editor runs the code: the menu's
    /// terrain in metres with Horizon levels, placed as Unity places its 3D objects (ObjectFactory.PlaceGameObject,
    /// UnityCsReference 2022.3 GOCreationCommands.Place) after its creation is registered for Undo; its
    /// material's toggles set property and keyword alike; the compute shaders found by the GUIDs their
    /// .meta files hold (and named as the scripts' default references); the converter deactivating its
    /// sources through Undo and leaving noise off; every dab and the disc at the clamped radius.
    /// Core's NewTerrainAuthoringTests, ResampleAuthoringTests and TileGroupAuthoringTests test the operations.
    /// </summary>
    [TestFixture]
    public class FirstHourSourceTests
    {
        static string Code(string path) => StripComments(File.ReadAllText(PackageRoot.Combine(path)));

        static string Body(string path, string method) => Methods(File.ReadAllText(PackageRoot.Combine(path))).Single(m => m.name == method).body;

        static string MetaGuid(string path) => Regex.Match(File.ReadAllText(PackageRoot.Combine(path + ".meta")), @"guid: (\w+)").Groups[1].Value;

        [Test]
        public void MenuTerrainIsInMetresWithHorizonLevelsAndPlacedAsUnityPlacesObjects()
        {
            string create = Body("Editor/GregoryTerrainMenu.cs", "Create");
            Assert.That(Code("Editor/GregoryTerrainMenu.cs"), Does.Not.Contain("localScale"), "the Transform keeps scale 1");
            StringAssert.Contains("TerrainSize = new Vector2((float)NewTerrainAuthoring.SizeMetres", create);
            StringAssert.Contains("HeightScale = (float)NewTerrainAuthoring.HeightMetres", create);
            StringAssert.Contains("HorizonLevels = true", create);
            StringAssert.Contains("NewTerrainAuthoring.CreateGrid()", create);
            StringAssert.Contains("TerrainAssets.AssignComputeShaders(renderer)", create);
            int undo = create.IndexOf("Undo.RegisterCreatedObjectUndo(go"), place = create.IndexOf("ObjectFactory.PlaceGameObject(go, parent)");
            Assert.That(undo, Is.GreaterThanOrEqualTo(0), "the creation is one undo step");
            Assert.That(place, Is.GreaterThan(undo), "placed (pivot, origin preference, parent, selection) after the creation is registered");
        }

        /// <summary>
        /// Review finding: the "...with Collider" object was made in the active scene before the terrain was
        /// placed, so with a prefab stage open (or a parent in another scene) it landed elsewhere.
        /// </summary>
        [Test]
        public void ColliderObjectIsPlacedBesideTheTerrain()
        {
            string create = Body("Editor/GregoryTerrainMenu.cs", "Create");
            int place = create.IndexOf("ObjectFactory.PlaceGameObject(go, parent)"), collider = create.IndexOf("AddColliderFollowingMainCamera(renderer)");
            Assert.That(collider, Is.GreaterThan(place), "the collider's object is made after the terrain is placed");
            StringAssert.Contains("PlaceBeside(child, renderer.gameObject)", Body("Editor/GregoryTerrainMenu.cs", "AddColliderFollowingMainCamera"));
            string beside = Body("Editor/GregoryTerrainMenu.cs", "PlaceBeside");
            StringAssert.Contains("SetParent(parent, false)", beside);
            StringAssert.Contains("SceneManager.MoveGameObjectToScene(go, placed.scene)", beside);
            // Review finding: in Prefab Mode the main camera lies in a scene the prefab cannot reference.
            StringAssert.Contains("EditorSceneManager.IsPreviewScene(child.scene) ? null : Camera.main", Body("Editor/GregoryTerrainMenu.cs", "AddColliderFollowingMainCamera"));
        }

        /// <summary>
        /// Review finding: "Fix import settings" wrote only the default platform's settings, which an
        /// override for the active platform (a compressed format, a smaller Max Size) beats.
        /// </summary>
        [Test]
        public void FixImportSetsTheActivePlatformToo()
        {
            string fix = Body("Editor/PatchGridWindow.cs", "FixImport");
            int platform = fix.IndexOf("FixPlatformSettings(importer, "), reimport = fix.IndexOf("SaveAndReimport()");
            Assert.That(platform, Is.GreaterThanOrEqualTo(0).And.LessThan(reimport), "the active platform's settings set before the reimport");
            string active = Body("Editor/PatchGridWindow.cs", "FixPlatformSettings");
            StringAssert.Contains("EditorUserBuildSettings.activeBuildTarget", active);
            StringAssert.Contains("TextureImporterFormat.RFloat", active);
            StringAssert.Contains("importer.SetPlatformTextureSettings(active)", active);
            StringAssert.Contains("GetDefaultPlatformTextureSettings()", active);
        }

        /// <summary>Unity's Terrain, Tree and Wind Zone are 3000-3002 in GameObject &gt; 3D Object (UnityCsReference 2022.3).</summary>
        [Test]
        public void MenuItemsSitBesideUnityTerrain()
        {
            var priorities = Regex.Matches(Code("Editor/GregoryTerrainMenu.cs"), @"MenuItem\(""GameObject/3D Object/[^""]+"", false, (\d+)\)")
                .Select(m => int.Parse(m.Groups[1].Value)).ToList();
            Assert.That(priorities, Has.Count.EqualTo(2));
            Assert.That(priorities, Has.All.InRange(3003, 3010), "in Unity Terrain's menu group (items within 10 of each other)");
        }

        [Test]
        public void NewMaterialSetsEveryShaderToggleExplicitly()
        {
            string shader = File.ReadAllText(PackageRoot.Combine("Shaders/GregoryTerrain.shader"));
            string material = Body("Editor/TerrainAssets.cs", "CreateMaterial");
            var toggles = Regex.Matches(shader, @"\[Toggle\((\w+)\)\]\s*(\w+)").Select(m => m.Groups[2].Value).ToList();
            Assert.That(toggles, Is.Not.Empty);
            foreach (string property in toggles)
                StringAssert.Contains($"SetToggle(material, \"{property}\"", material, $"{property} set with its keyword");
        }

        [Test]
        public void ComputeShadersAreFoundByTheirMetaGuids()
        {
            string assets = Code("Editor/TerrainAssets.cs");
            string renderer = File.ReadAllText(PackageRoot.Combine("Runtime/GregoryTerrainRenderer.cs.meta"));
            string snow = File.ReadAllText(PackageRoot.Combine("Runtime/SnowSimulator.cs.meta"));
            (string constant, string shader, string meta, string field)[] shaders =
            {
                ("CacheShaderGuid", "Shaders/Cache/TerrainCache.compute", renderer, "cacheShader"),
                ("SnowSimulationGuid", "Shaders/Snow/SnowSimulation.compute", snow, "simulation"),
                ("SnowFieldGuid", "Shaders/Snow/SnowField.compute", snow, "fieldShader"),
            };
            foreach (var s in shaders)
            {
                string guid = MetaGuid(s.shader);
                StringAssert.Contains($"{s.constant} = \"{guid}\"", assets, s.shader);
                StringAssert.Contains($"- {s.field}: {{fileID: 7200000, guid: {guid}, type: 3}}", s.meta, $"default reference of {s.field}");
            }
        }

        [Test]
        public void ConverterDeactivatesItsSourcesThroughUndoWithNoiseOff()
        {
            string code = Code("Editor/Import/TerrainConversion.cs");
            Assert.That(code, Does.Not.Contain("localScale"), "the Transform keeps scale 1");
            StringAssert.Contains("CreateMaterial(go, noise: false)", code);
            string deactivate = Body("Editor/Import/TerrainConversion.cs", "Deactivate");
            int record = deactivate.IndexOf("Undo.RecordObject(t.gameObject"), off = deactivate.IndexOf("SetActive(false)");
            Assert.That(record, Is.GreaterThanOrEqualTo(0));
            Assert.That(off, Is.GreaterThan(record), "recorded before it is changed");
            string convert = Body("Editor/Import/TerrainConversion.cs", "Convert");
            Assert.That(convert.IndexOf("TileGroupAuthoring.FitAndJoin"), Is.LessThan(convert.IndexOf("Create(first")), "the whole fit runs before anything is made");
            Assert.That(convert.IndexOf("Create(first"), Is.LessThan(convert.IndexOf("Deactivate(terrains)")));
        }

        [Test]
        public void DabsAndDiscUseTheClampedRadius()
        {
            string tool = "Editor/PatchGridSculptTool.cs";
            foreach (string method in new[] { "Dab", "OnToolGUI" })
            {
                string body = Body(tool, method);
                StringAssert.Contains("BrushRadius(renderer)", body, method);
                Assert.That(Regex.IsMatch(body, @"RadiusMetres\s*[/*,)]"), Is.False, $"{method} uses the typed radius unclamped");
            }
            StringAssert.Contains("ClampBrushRadius(RadiusMetres, spacing)", Body(tool, "BrushRadius"));
        }
        [Test]
        public void EditorCodeNeverTestsAComponentWithIs()
        {
            // In the editor GetComponent returns a fake-null object for a missing component; `is T` and
            // `?.` test the C# reference, so every selected GameObject would pass as a Terrain.
            foreach (string file in Directory.GetFiles(PackageRoot.Combine("Editor"), "*.cs", SearchOption.AllDirectories))
            {
                string code = StripComments(File.ReadAllText(file));
                Assert.That(Regex.IsMatch(code, @"GetComponent<\w+>\(\)\s*(is\s|\?\.)"), Is.False, $"{Path.GetFileName(file)} tests GetComponent's result with `is` or `?.`");
            }
        }

        [Test]
        public void NewGridsAreOnDiskWithTheirBlocksAndAFailedConversionLeavesNothing()
        {
            string grid = Body("Editor/TerrainAssets.cs", "CreateGrid");
            Assert.That(grid.IndexOf("AssetDatabase.SaveAssetIfDirty(asset)"), Is.GreaterThan(grid.IndexOf("AddObjectToAsset")),
                "AddObjectToAsset changes memory only: the blocks reach the file when it is saved");
            string create = Body("Editor/Import/TerrainConversion.cs", "Create");
            Assert.That(create.IndexOf("TerrainSize ="), Is.LessThan(create.IndexOf("TerrainAssets.CreateGrid")), "the sizes are refused before an asset is made");
            StringAssert.Contains("UnityEngine.Object.DestroyImmediate(go)", create);
            StringAssert.Contains("AssetDatabase.DeleteAsset(AssetDatabase.GetAssetPath(asset))", create);
            StringAssert.Contains("AssetFileName(southWest.Name)", create);
        }
    }
}
