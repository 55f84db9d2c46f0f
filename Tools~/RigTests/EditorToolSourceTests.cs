using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Static checks over the editor tools (Editor/**/*.cs) for what only a Unity editor shows running
    /// (issue 36): Scene-view control points placed by the renderer's world frame, not the Transform's
    /// matrix alone; the sculpt shortcut guarded as Unity guards its own tool shortcuts; a GUI pass
    /// left with GUIUtility.ExitGUI after each modal dialog; the sculpt drag holding
    /// GUIUtility.hotControl so its release is seen outside the Scene view. Each rule is checked as
    /// Unity's own editors follow it (UnityCsReference 2022.3, read for each) and is run on the code it
    /// replaced, which it must reject.
    /// </summary>
    [TestFixture]
    public class EditorToolSourceTests
    {
        static Dictionary<string, string> EditorSources() =>
            Directory.GetFiles(PackageRoot.Combine("Editor"), "*.cs", SearchOption.AllDirectories)
                .ToDictionary(f => Path.GetRelativePath(PackageRoot.Path, f).Replace('\\', '/'), File.ReadAllText);

        internal static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        /// <summary>Methods of a C# file: name -> body (block or expression), comments stripped. Good enough for this package's code.</summary>
        internal static List<(string name, string body)> Methods(string code)
        {
            code = StripComments(code);
            var result = new List<(string, string)>();
            var header = new Regex(@"(?<![\w.])(?:(?:static|public|private|internal|protected|override|virtual|sealed)\s+)*[\w<>\[\],?]+\s+(?<name>\w+)\s*\((?<args>[^()]*(?:\([^()]*\)[^()]*)*)\)\s*(?<open>\{|=>)");
            foreach (Match m in header.Matches(code))
            {
                string name = m.Groups["name"].Value;
                if (name == "if" || name == "while" || name == "for" || name == "foreach" || name == "switch" || name == "using" || name == "catch" || name == "lock") continue;
                int start = m.Index + m.Length;
                if (m.Groups["open"].Value == "=>")
                {
                    int end = code.IndexOf(';', start);
                    result.Add((name, code.Substring(start, end - start + 1)));
                    continue;
                }
                int depth = 1, k = start;
                while (k < code.Length && depth > 0)
                {
                    if (code[k] == '{') depth++;
                    else if (code[k] == '}') depth--;
                    k++;
                }
                result.Add((name, code.Substring(start, k - 1 - start)));
            }
            return result;
        }

        // ---- 2. Scene-view positions through the renderer's frame ----------------------------------

        /// <summary>Editor code that places Scene-view drawing by the Transform's matrix (ignores Terrain Size, Height Scale and the origin offset).</summary>
        internal static List<string> TransformOnlyPlacements(IDictionary<string, string> files) =>
            files.SelectMany(f => Regex.Matches(StripComments(f.Value), @"[^\n]*\b(?:localToWorldMatrix|worldToLocalMatrix|TransformPoint|InverseTransformPoint)\b[^\n]*")
                .Select(m => $"{f.Key}: {m.Value.Trim()}")).ToList();

        [Test]
        public void SceneViewHandlesGoThroughTheRenderersWorldFrame()
        {
            var files = EditorSources();
            Assert.That(TransformOnlyPlacements(files), Is.Empty,
                "Scene-view control points, wireframe, handles and outlines must use the renderer's WorldFrame (Terrain Size, Height Scale, origin offset), as its draw matrices do");
            foreach (string file in new[] { "Editor/GregoryTerrainRendererEditor.cs", "Editor/PatchGridSculptTool.cs" })
                Assert.That(StripComments(files[file]), Does.Contain("TerrainScenePoints.TryGet("), $"{file} draws through TerrainScenePoints");
            Assert.That(StripComments(files["Editor/GregoryTerrainRendererEditor.cs"]), Does.Match(@"MoveControlPoint\([^;]*points\.ToTerrain\("),
                "a handle's world position goes back through the same frame");
        }

        [Test]
        public void FramePlacementCheckRejectsTheTransformMatrix()
        {
            var old = new Dictionary<string, string>
            {
                ["A.cs"] = "void OnSceneGUI() { Handles.matrix = r.transform.localToWorldMatrix; // draw\n Handles.DrawLine(a, b); }",
                ["B.cs"] = "Vector3 p = renderer.transform.TransformPoint(ToObject(cp));",
            };
            Assert.That(TransformOnlyPlacements(old).Count, Is.EqualTo(2));
            Assert.That(TransformOnlyPlacements(new Dictionary<string, string> { ["C.cs"] = "// not localToWorldMatrix\nHandles.matrix = Matrix4x4.identity;" }), Is.Empty);
        }

        // ---- 3. The sculpt shortcut guarded -------------------------------------------------------

        /// <summary>
        /// Methods that call <c>ToolManager.SetActiveTool</c> without first returning when the tool is
        /// not available (Unity throws InvalidOperationException when the selection has no component
        /// the tool edits; its own tool shortcuts check and return, e.g. "Tools/Cycle Tool Modes").
        /// </summary>
        internal static List<string> UnguardedToolActivations(IDictionary<string, string> files)
        {
            var found = new List<string>();
            foreach (var f in files)
                foreach (var (name, body) in Methods(f.Value))
                {
                    int call = body.IndexOf("SetActiveTool", System.StringComparison.Ordinal);
                    if (call < 0) continue;
                    if (!Regex.IsMatch(body.Substring(0, call), @"\bif\s*\([^;]*\)\s*(?:\{[^}]*)?\breturn\b"))
                        found.Add($"{f.Key}: {name}");
                }
            return found;
        }

        [Test]
        public void ToolShortcutsReturnWhenTheToolIsNotAvailable()
        {
            var files = EditorSources();
            Assert.That(StripComments(files["Editor/GregoryTerrainShortcuts.cs"]), Does.Contain("SetActiveTool"), "the sculpt shortcut exists");
            Assert.That(UnguardedToolActivations(files), Is.Empty, "SetActiveTool throws without a selected terrain: check and return first");
        }

        [Test]
        public void ToolGuardCheckRejectsTheBareCall()
        {
            var old = new Dictionary<string, string> { ["S.cs"] = "[Shortcut(\"Gregory Terrain/Sculpt Tool\", typeof(SceneView), KeyCode.B)]\nstatic void SculptTool() => UnityEditor.EditorTools.ToolManager.SetActiveTool<PatchGridSculptTool>();" };
            Assert.That(UnguardedToolActivations(old), Is.EqualTo(new[] { "S.cs: SculptTool" }));
            var guarded = new Dictionary<string, string> { ["S.cs"] = "static void SculptTool()\n{\n if (!Available()) { Note(); return; }\n ToolManager.SetActiveTool<T>();\n}" };
            Assert.That(UnguardedToolActivations(guarded), Is.Empty);
        }

        // ---- 4. GUIUtility.ExitGUI after modal dialogs ---------------------------------------------

        const string DialogCall = @"EditorUtility\.(?:OpenFilePanel|OpenFilePanelWithFilters|SaveFilePanel|SaveFilePanelInProject|OpenFolderPanel|SaveFolderPanel|DisplayDialog|DisplayDialogComplex)\s*\(";
        static readonly string[] GuiCallbacks = { "OnGUI", "OnInspectorGUI", "OnSceneGUI", "OnToolGUI", "OnPreviewGUI" };

        /// <summary>
        /// Calls, in a GUI callback, of a modal dialog or of a method of the same file that (through
        /// others) opens one, not followed at once by <c>GUIUtility.ExitGUI();</c>. Unity's own
        /// editors leave the GUI pass after a dialog (GraphicsSettingsEditors, VideoPlayerEditor):
        /// the modal loop ran other GUI meanwhile and this pass's layout no longer holds.
        /// </summary>
        internal static List<string> DialogsWithoutExitGui(IDictionary<string, string> files)
        {
            var found = new List<string>();
            foreach (var f in files)
            {
                var methods = Methods(f.Value);
                var opens = new HashSet<string>(methods.Where(m => Regex.IsMatch(m.body, DialogCall)).Select(m => m.name));
                for (bool grew = true; grew;)
                {
                    grew = false;
                    foreach (var (name, body) in methods)
                        if (!opens.Contains(name) && opens.Any(o => o != name && Regex.IsMatch(body, $@"(?<![\w.]){o}\s*\(")))
                            grew |= opens.Add(name);
                }
                foreach (var (name, body) in methods.Where(m => GuiCallbacks.Contains(m.name)))
                {
                    string calls = opens.Count == 0 ? DialogCall : $@"(?:{DialogCall}|(?<![\w.])(?:{string.Join("|", opens)})\s*\()";
                    foreach (Match c in Regex.Matches(body, calls))
                    {
                        int end = StatementEnd(body, c.Index + c.Length);
                        if (!Regex.IsMatch(body.Substring(end), @"^\s*GUIUtility\.ExitGUI\s*\(\s*\)\s*;"))
                            found.Add($"{f.Key}: {name} calls {c.Value.TrimEnd('(', ' ')} without GUIUtility.ExitGUI() after it");
                    }
                }
            }
            return found;
        }

        /// <summary>Index just after the <c>;</c> closing the statement whose call's argument list starts before <paramref name="from"/>.</summary>
        static int StatementEnd(string code, int from)
        {
            int depth = 1, k = from;
            while (k < code.Length && depth > 0)
            {
                if (code[k] == '(') depth++;
                else if (code[k] == ')') depth--;
                k++;
            }
            int semi = code.IndexOf(';', k);
            return semi < 0 ? code.Length : semi + 1;
        }

        [Test]
        public void ModalDialogsInGuiAreFollowedByExitGui()
        {
            var files = EditorSources();
            Assert.That(files.Values.Count(v => Regex.IsMatch(v, DialogCall)), Is.GreaterThanOrEqualTo(2), "the editor opens file dialogs");
            Assert.That(DialogsWithoutExitGui(files), Is.Empty);
        }

        [Test]
        public void ExitGuiCheckRejectsADialogLeftInTheGuiPass()
        {
            var old = new Dictionary<string, string>
            {
                ["Inspector.cs"] = "public override void OnInspectorGUI()\n{\n if (GUILayout.Button(ExportLabel)) Export(asset);\n if (GUILayout.Button(b)) { string p = EditorUtility.OpenFilePanel(\"a\", \"\", \"json\"); Use(p); }\n}\n" +
                                   "static void Export(PatchGridAsset asset)\n{\n string path = EditorUtility.SaveFilePanel(\"Export\", \"\", asset.name + \".json\", \"json\");\n if (string.IsNullOrEmpty(path)) return;\n}",
                ["Window.cs"] = "void OnGUI()\n{\n if (GUILayout.Button(new GUIContent(\"Fit to RAW file...\", \"tip\"))) FitRaw();\n}\nvoid FitRaw() { if (ReadRaw(out double[] h)) Fit(h); }\nbool ReadRaw(out double[] h) { h = null; string path = EditorUtility.OpenFilePanel(\"RAW\", \"\", \"\"); return path != null; }",
            };
            Assert.That(DialogsWithoutExitGui(old).Count, Is.EqualTo(3), string.Join("\n", DialogsWithoutExitGui(old)));
            var fixedCode = new Dictionary<string, string>
            {
                ["Window.cs"] = "void OnGUI()\n{\n if (GUILayout.Button(new GUIContent(\"Fit\", \"tip\"))) { FitRaw(); GUIUtility.ExitGUI(); }\n}\nvoid FitRaw() { string path = EditorUtility.OpenFilePanel(\"RAW\", \"\", \"\"); }",
            };
            Assert.That(DialogsWithoutExitGui(fixedCode), Is.Empty);
        }

        // ---- 5. The sculpt drag holds the hot control ----------------------------------------------

        /// <summary>
        /// What an EditorTool that handles mouse drags lacks of Unity's drag protocol (TerrainInspector's
        /// paint tools in 2022.3): the event type read for its control (GetTypeForControl), the hot
        /// control taken on a MouseDown no nearer control wants (HandleUtility.nearestControl), drags and
        /// the release taken only while it holds it, and given back
        /// (hotControl = 0). Without it a release outside the Scene view never reaches the tool.
        /// </summary>
        internal static List<string> DragProtocolGaps(string code)
        {
            code = StripComments(code);
            var gaps = new List<string>();
            if (!code.Contains("EventType.MouseDrag")) return gaps;
            if (!Regex.IsMatch(code, @"\.GetTypeForControl\s*\(\s*id\s*\)")) gaps.Add("event type not read with GetTypeForControl(id)");
            if (!Regex.IsMatch(code, @"GUIUtility\.hotControl\s*=(?!=)[^;]*\bid\s*;")) gaps.Add("hot control not taken (GUIUtility.hotControl = id)");
            if (!Regex.IsMatch(code, @"GUIUtility\.hotControl\s*=\s*0\s*;")) gaps.Add("hot control not given back (GUIUtility.hotControl = 0)");
            if (!Regex.IsMatch(code, @"EventType\.MouseDown\s+when[^:]*HandleUtility\.nearestControl\s*==\s*id")) gaps.Add("a click taken though another control is nearer (HandleUtility.nearestControl)");
            if (!Regex.IsMatch(code, @"EventType\.MouseDrag\s+when\s+GUIUtility\.hotControl\s*==\s*id")) gaps.Add("drags not confined to the hot control");
            if (!Regex.IsMatch(code, @"EventType\.MouseUp\s*&&\s*GUIUtility\.hotControl\s*==\s*id|EventType\.MouseUp\s+when\s+GUIUtility\.hotControl\s*==\s*id")) gaps.Add("the release not taken by the hot control");
            return gaps;
        }

        [Test]
        public void SculptToolHoldsTheHotControlDuringADrag()
        {
            var files = EditorSources();
            Assert.That(DragProtocolGaps(files["Editor/PatchGridSculptTool.cs"]), Is.Empty);
            foreach (var f in files.Where(f => Regex.IsMatch(f.Value, @":\s*EditorTool\b")))
                Assert.That(DragProtocolGaps(f.Value), Is.Empty, f.Key);
        }

        [Test]
        public void HotControlCheckRejectsADragWithoutIt()
        {
            string old = "int id = GUIUtility.GetControlID(FocusType.Passive);\nif (e.type == EventType.Layout) HandleUtility.AddDefaultControl(id);\nswitch (e.type)\n{\n" +
                         " case EventType.MouseDown when e.button == 0 && hit: BeginStroke(); e.Use(); break;\n" +
                         " case EventType.MouseDrag when e.button == 0 && (_strokeGrid != null): Dab(); e.Use(); break;\n" +
                         " case EventType.MouseUp when e.button == 0 && (_strokeGrid != null): EndStroke(); e.Use(); break;\n}";
            Assert.That(DragProtocolGaps(old).Count, Is.EqualTo(6), string.Join("; ", DragProtocolGaps(old)));
        }
        // ---- 6, 7, 9: the grid asset's whole-grid work once per content change, not per dab or load ----

        /// <summary>
        /// Where the authoring code does whole-grid work it should not (issue 36): the asset validating
        /// every grid Unity loads (OnEnable) or again on each conversion; the renderer re-uploading and the
        /// query rebuilding the whole grid on a dab without first catching up on the edited patches; a
        /// whole-grid replacement recording every block for Undo. Keys: file name -> C#.
        /// </summary>
        internal static List<string> WholeGridWorkGaps(IDictionary<string, string> files)
        {
            var gaps = new List<string>();
            string Body(string file, string method) =>
                Methods(files[file]).Where(m => m.name == method).Select(m => m.body).FirstOrDefault() ?? "";
            string onEnable = Body("PatchGridAsset.cs", "OnEnable");
            if (Regex.IsMatch(onEnable, @"\b(MarkChanged|CheckSerializedData)\s*\(\s*\)")) gaps.Add("PatchGridAsset.OnEnable validates the whole grid at every load");
            foreach (var (name, body) in Methods(files["PatchGridAsset.cs"]))
                if (name != "MarkChanged" && name != "MoveLegacyDataToBlocks" && name != "CheckSerializedData" && Regex.IsMatch(body, @"\bCheckSerializedData\s*\(\s*\)"))
                    gaps.Add($"PatchGridAsset.{name} validates the whole grid again instead of using the verdict kept since the last change");
            string apply = Body("PatchGridAsset.cs", "ApplyEdit");
            if (!Regex.IsMatch(apply, @"_changes\.Add\s*\(")) gaps.Add("PatchGridAsset.ApplyEdit does not log the patches it changed for readers to catch up");
            string upload = Body("TerrainFrameDriver.cs", "EnsureUploaded");
            int partial = upload.IndexOf("TryUploadEditedPatches(", System.StringComparison.Ordinal), release = upload.IndexOf("ReleaseGpuResources()", System.StringComparison.Ordinal);
            if (partial < 0 || release >= 0 && partial > release) gaps.Add("the renderer uploads the whole grid on an edit without first uploading the edited patches only");
            string queries = StripComments(files["GregoryTerrainSurface.cs"]);
            int edited = queries.IndexOf("EditedQuery(", System.StringComparison.Ordinal), rebuilt = queries.IndexOf("new TerrainSurfaceQuery(", System.StringComparison.Ordinal);
            if (edited < 0 || rebuilt >= 0 && edited > rebuilt) gaps.Add("the query is rebuilt on an edit without first catching up on the edited patches");
            string setGrid = Body("PatchGridAssetUndo.cs", "SetGrid");
            Match recorded = Regex.Match(setGrid, @"Undo\.RecordObjects\s*\(\s*(\w+)");
            if (!recorded.Success || !Regex.IsMatch(setGrid, $@"\b{recorded.Groups[1].Value}\s*=\s*asset\.BlocksChangedBy\s*\("))
                gaps.Add("a whole-grid replacement records blocks whose bits do not change");
            return gaps;
        }

        static Dictionary<string, string> AuthoringSources()
        {
            var files = new Dictionary<string, string>();
            foreach (string name in new[] { "PatchGridAsset.cs", "TerrainFrameDriver.cs", "GregoryTerrainSurface.cs" })
                files[name] = File.ReadAllText(PackageRoot.Combine("Runtime", name));
            files["PatchGridAssetUndo.cs"] = File.ReadAllText(PackageRoot.Combine("Editor", "PatchGridAssetUndo.cs"));
            return files;
        }

        [Test]
        public void WholeGridWorkRunsOncePerContentChange()
        {
            Assert.That(WholeGridWorkGaps(AuthoringSources()), Is.Empty);
        }

        [Test]
        public void WholeGridWorkCheckRejectsTheOldPaths()
        {
            var old = new Dictionary<string, string>
            {
                ["PatchGridAsset.cs"] = "void OnEnable() => MarkChanged();\npublic void MarkChanged() { _error = CheckSerializedData(); }\n" +
                                        "internal PatchGrid ToPatchGrid()\n{\n string error = CheckSerializedData();\n return null;\n}\n" +
                                        "internal void ApplyEdit(PatchEdit edit)\n{\n _version = s_NextVersion++;\n _fingerprint = Fingerprint();\n}",
                ["TerrainFrameDriver.cs"] = "bool EnsureUploaded()\n{\n if (_uploadedVersion == grid.Version) return true;\n ReleaseGpuResources();\n return true;\n}",
                ["GregoryTerrainSurface.cs"] = "try { _query = new TerrainSurfaceQuery(grid.ToPatchGrid(), noise, keywords); }",
                ["PatchGridAssetUndo.cs"] = "public static void SetGrid(PatchGridAsset asset, PatchGrid grid, string undoName)\n{\n Undo.RecordObject(asset, undoName);\n" +
                                            " PatchGridBlock[] existing = asset.Blocks;\n if (existing.Length > 0) Undo.RecordObjects(existing, undoName);\n}",
            };
            Assert.That(WholeGridWorkGaps(old).Count, Is.EqualTo(6), string.Join("\n", WholeGridWorkGaps(old)));
        }
        // ---- 8. Fit to texture reads the file's heights or refuses ----------------------------------

        /// <summary>
        /// Methods that read a texture's texels (GetRawTextureData, GetPixels) without first checking,
        /// through a method of the same file, that the import holds its file's heights: the file's size
        /// from its importer (GetSourceTextureWidthAndHeight: Max Size and Non-Power of 2 scaling
        /// resample) and an uncompressed format (GraphicsFormatUtility.IsCompressedFormat).
        /// </summary>
        internal static List<string> UncheckedTextureReads(string code)
        {
            var methods = Methods(code);
            var checks = methods.Where(m => m.body.Contains("GetSourceTextureWidthAndHeight(") && m.body.Contains("IsCompressedFormat(")).Select(m => m.name).ToList();
            var found = new List<string>();
            foreach (var (name, body) in methods)
            {
                Match read = Regex.Match(body, @"\.(GetRawTextureData|GetPixels)\s*\(");
                if (!read.Success) continue;
                string before = body.Substring(0, read.Index);
                if (!checks.Any(c => Regex.IsMatch(before, $@"(?<![\w.]){c}\s*\(")) || !Regex.IsMatch(before, @"\breturn\b"))
                    found.Add($"{name} reads {read.Groups[1].Value} without checking the import against the file");
            }
            return found;
        }

        [Test]
        public void FitToTextureChecksTheImportAgainstItsFile()
        {
            string window = EditorSources()["Editor/PatchGridWindow.cs"];
            Assert.That(window, Does.Contain("GetRawTextureData"), "the window reads texels");
            Assert.That(UncheckedTextureReads(window), Is.Empty);
        }

        [Test]
        public void TextureReadCheckRejectsAReadOfTheImportAsIs()
        {
            string old = "bool ReadTexture(out double[] heights)\n{\n heights = null;\n if (!heightmap.isReadable) { Report(\"not readable\"); return false; }\n" +
                         " heights = TextureHeights.Decode(heightmap.name, heightmap.GetRawTextureData(), heightmap.width, heightmap.height, texel);\n return true;\n}";
            Assert.That(UncheckedTextureReads(old), Is.EqualTo(new[] { "ReadTexture reads GetRawTextureData without checking the import against the file" }));
        }
    }
}
