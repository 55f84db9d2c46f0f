using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's inspector names its fields as strings (SerializedObject.FindProperty), listed
    /// once in RendererInspectorLayout.Sections: a misspelt name is a null property and an exception
    /// in the editor, a field left out is a setting users cannot reach. Every serialized field of
    /// GregoryTerrainRenderer must be listed exactly once, every name listed must be a serialized
    /// field, and the inspector must draw the sections from that list.
    /// </summary>
    [TestFixture]
    public class RendererInspectorTests
    {
        static readonly Regex SerializedField = new Regex(@"\[SerializeField(?<attrs>[^\]]*)\]\s*(?<type>[\w<>\[\].]+)\s+(?<name>\w+)\s*[=;]");
        static readonly Regex PublicField = new Regex(@"^\s*public\s+(?!static\b|const\b|readonly\b|event\b)[\w<>\[\].]+\s+(\w+)\s*(?:=[^;>]*)?;", RegexOptions.Multiline);

        internal static List<string> RendererFields()
        {
            var names = new List<string>();
            foreach (string path in Directory.GetFiles(PackageRoot.Combine("Runtime"), "GregoryTerrainRenderer*.cs"))
            {
                string code = File.ReadAllText(path);
                // Hidden fields are not drawn (the old flat layout); a settings struct is drawn field by field.
                foreach (Match m in SerializedField.Matches(code).Cast<Match>().Where(m => !m.Groups["attrs"].Value.Contains("HideInInspector")))
                {
                    string name = m.Groups["name"].Value;
                    var (_, fields) = RendererInspectorLayout.Structs.FirstOrDefault(s => s.field == name);
                    if (fields == null) names.Add(name);
                    else names.AddRange(fields.Select(f => name + "." + f.name));
                }
                names.AddRange(PublicField.Matches(code).Select(m => m.Groups[1].Value));
            }
            return names;
        }

        static List<string> Listed() => RendererInspectorLayout.Sections.SelectMany(s => s.fields).ToList();

        static string EditorSource() => File.ReadAllText(PackageRoot.Combine("Editor", "GregoryTerrainRendererEditor.cs"));

        /// <summary>What is wrong between the fields and the names the inspector draws.</summary>
        public static List<string> Problems(IReadOnlyCollection<string> fields, IReadOnlyList<string> drawn)
        {
            var problems = new List<string>();
            problems.AddRange(fields.Where(f => !drawn.Contains(f)).Select(f => $"field {f} is not drawn"));
            problems.AddRange(drawn.Where(d => !fields.Contains(d)).Distinct().Select(d => $"\"{d}\" is drawn but is no serialized field"));
            problems.AddRange(drawn.GroupBy(d => d).Where(g => g.Count() > 1).Select(g => $"\"{g.Key}\" is drawn {g.Count()} times"));
            return problems;
        }

        [Test]
        public void EveryRendererFieldIsDrawnOnce()
        {
            var fields = RendererFields();
            Assert.That(fields, Has.Count.GreaterThanOrEqualTo(25), "too few serialized fields found: is the scan still reading the renderer?");
            Assert.That(fields, Does.Contain("grid").And.Contain("debugShowPatchWireframe"));
            var problems = Problems(fields, Listed());
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
            // The editor draws the listed sections and names no field of its own (PropertyField by a literal).
            string source = EditorSource();
            Assert.That(source, Does.Contain("RendererInspectorLayout.Sections"));
            Assert.That(NamedFields(source).Where(n => !fields.Contains(n)), Is.Empty,
                "a FindProperty or P literal in the editor that is no serialized field");
        }

        /// <summary>Field names the editor passes as literals, to FindProperty or its shorthand P.</summary>
        internal static IEnumerable<string> NamedFields(string source) =>
            Regex.Matches(source, @"\b(?:FindProperty|P)\(""([\w.]+)""\)").Select(m => m.Groups[1].Value);

        [Test]
        public void AFieldNamedThroughTheShorthandIsChecked() =>
            Assert.That(NamedFields("SerializedProperty[] p = { P(\"tessellation.targetPixelErr\"), FindProperty(\"tiles\") };"),
                Is.EquivalentTo(new[] { "tessellation.targetPixelErr", "tiles" }));

        [Test]
        public void AMisspeltOrMissingFieldIsCaught()
        {
            var fields = RendererFields();
            var listed = Listed();
            Assert.That(listed, Does.Contain("tessellation.targetPixels"));
            Assert.That(Problems(fields, listed.Select(f => f == "tessellation.targetPixels" ? "tessellation.targetPixel" : f).ToList()),
                Is.EquivalentTo(new[] { "field tessellation.targetPixels is not drawn", "\"tessellation.targetPixel\" is drawn but is no serialized field" }));
            Assert.That(Problems(fields, listed.Where(f => f != "cacheShader").ToList()), Is.EquivalentTo(new[] { "field cacheShader is not drawn" }));
            Assert.That(Problems(fields, listed.Append("grid").ToList()), Is.EquivalentTo(new[] { "\"grid\" is drawn 2 times" }));
        }
    }

    /// <summary>
    /// The review of the renderer inspector against Unity 2022.3: what the editor C# must do that
    /// only a Unity editor can run, checked as source patterns (each names the fault it keeps out).
    /// </summary>
    [TestFixture]
    public class RendererInspectorReviewTests
    {
        static string Src(params string[] path) => File.ReadAllText(PackageRoot.Combine(path));
        static string Editor() => Src("Editor", "GregoryTerrainRendererEditor.cs");

        /// <summary>The text of method <paramref name="name"/> up to the next member at its indentation.</summary>
        static string Body(string source, string name)
        {
            Match m = Regex.Match(source, @"\b" + name + @"\([^)]*\)\s*(?:=>[^;]*;|\{.*?\n        \})", RegexOptions.Singleline);
            Assert.That(m.Success, $"no method {name}");
            return m.Value;
        }

        [TestCase("ZoomRangeController.cs"), TestCase("CameraRangeController.cs")]
        public void ADisabledRangeControllerGivesTheSavedRangeBack(string file) =>
            // Undo of the add, Remove Component, the checkbox: each runs OnDisable ([ExecuteAlways]).
            Assert.That(Body(Src("Runtime", file), "OnDisable"), Does.Contain("target.SyncRangeFromSerialized()"));

        /// <summary>F frames the drawn terrain, not the Transform's corner (editor-only: the source is checked).</summary>
        [Test]
        public void FFramesTheTerrain()
        {
            // Review finding: "=> true" framed a unit box at the origin for a terrain that had not drawn, and
            // only the first of several selected terrains.
            Assert.That(Editor(), Does.Contain("bool HasFrameBounds() => targets.Any(t => Drawn(t as GregoryTerrainRenderer));"));
            string bounds = Body(Editor(), "OnGetFrameBounds");
            Assert.That(bounds, Does.Contain("foreach (UnityEngine.Object t in targets)").And.Contain("Encapsulate(b)").And.Contain("WorldBounds()"));
            Assert.That(Body(Editor(), "Drawn"), Does.Contain("r.isActiveAndEnabled && r.HasDrawn"));
        }

        /// <summary>
        /// Review findings: the levels' estimate laid out the serialized Tiles (an edit not yet checked:
        /// Tiles 6 threw out of the inspector); the range-side field's C# pattern let a fake-null target
        /// through (UnassignedReferenceException on every repaint of a multi-selection).
        /// </summary>
        [Test]
        public void EstimateAndRangeSideSurviveEditsAndEmptyTargets()
        {
            string estimate = File.ReadAllText(PackageRoot.Combine("Runtime/GregoryTerrainSurface.cs"));
            Assert.That(estimate, Does.Contain("int uploadedTiles = inputs.TileCountInt();"));
            Assert.That(estimate, Does.Contain("LodLevels.Layout(new Double2(local.x, local.z), r.FinestExponent(), uploadedTiles, _levels)"));
            string side = File.ReadAllText(PackageRoot.Combine("Editor/CameraRangeControllerEditor.cs"));
            Assert.That(side, Does.Not.Contain("is GregoryTerrainRenderer o"));
            Assert.That(side, Does.Contain("a != null && a.WorldUnitsPerObjectUnit.Equals(b.WorldUnitsPerObjectUnit)"));
        }

        [Test]
        public void OpenWorldWritesEachRenderersOwnTiles()
        {
            string view = Body(Editor(), "DrawViewMode");
            Assert.That(view, Does.Not.Contain("FindProperty(\"tiles\")"), "a multi-object tiles property writes the first renderer's tiles to all");
            Assert.That(Editor(), Does.Contain("new SerializedObject(t)"));
        }

        [Test]
        public void ZoomFindsControllersAnywhereAndStopsCameraRangeControllers()
        {
            string e = Editor();
            Assert.That(e, Does.Contain("FindObjectsByType<ZoomRangeController>").And.Contain("FindObjectsByType<CameraRangeController>"));
            Assert.That(Body(e, "ModeOf"), Does.Not.Contain("GetComponents"), "a controller on another object is a zoom too");
        }

        [Test]
        public void ControllersAreEnabledThroughSerializedPropertiesForPrefabOverrides()
        {
            Assert.That(Regex.IsMatch(Editor(), @"\.enabled\s*=[^=]"), Is.False, "Behaviour.enabled set directly records no prefab override");
            Assert.That(Editor(), Does.Contain("\"m_Enabled\""));
        }

        [Test]
        public void CellSizesApplyWhenTypingEnds() =>
            Assert.That(Body(Editor(), "DrawMetresField"), Does.Not.Contain("EditorGUI.FloatField(").And.Contain("EditorGUI.DelayedFloatField("));

        [Test]
        public void ViewModeReadsEverySelectedRenderer() =>
            Assert.That(Body(Editor(), "DrawViewMode"), Does.Not.Contain("(GregoryTerrainRenderer)target").And.Contain("CommonMode("));

        [Test]
        public void QualityIsOneNamedUndoStepWrittenAsInts()
        {
            string q = Body(Editor(), "DrawQuality");
            Assert.That(q, Does.Contain("Undo.SetCurrentGroupName(\"Quality \""));
            Assert.That(Editor(), Does.Not.Contain("enumValueIndex"), "enumValueIndex is the index in the enum's names, not its value");
            Assert.That(Editor(), Does.Not.Contain("paper's"), "tooltips in plain words");
        }

        [Test]
        public void PatchGridWindowKeepsOldSettingsAndSearchesTheSceneOnlyWhenItChanges()
        {
            string w = Src("Editor", "PatchGridWindow.cs");
            Assert.That(w, Does.Match(@"\[SerializeField, FormerlySerializedAs\(""heightScale""\)\] float sampleHeight"));
            Assert.That(w, Does.Match(@"\[SerializeField, FormerlySerializedAs\(""widthMetres""\)\] float metresPerHeightUnit"));
            Assert.That(Body(w, "DrawMetresPerHeightUnit"), Does.Not.Contain("FindObjectsByType"), "a scene search on every GUI event");
            Assert.That(w, Does.Contain("EditorApplication.hierarchyChanged +=").And.Contain("EditorApplication.hierarchyChanged -="));
            Assert.That(w, Does.Not.Contain("'s Height Scale)"), "the value is Height Scale times the Transform's y scale");
        }
    }
}
