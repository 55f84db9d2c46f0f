using System;
using System.Collections.Generic;
using System.Linq;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Renderer inspector: readouts, help boxes, then the settings in foldouts (open state in
    /// EditorPrefs), each field where it acts. Scene view: control points and patch wireframe, points
    /// moved with undoable position handles; keys in GregoryTerrainShortcuts.
    /// </summary>
    [CustomEditor(typeof(GregoryTerrainRenderer)), CanEditMultipleObjects]
    internal sealed class GregoryTerrainRendererEditor : Editor
    {
        int _selectedPatch = -1, _selectedSlot = -1;
        int _nearPatch = -1;   // the patch whose neighbourhood shows control-point buttons
        // The in-view estimate evaluates up to 256 tiles on the CPU: on Layout events, at most every EstimateSeconds.
        const double EstimateSeconds = 0.25;
        double _estimateTime = double.NegativeInfinity;
        string _estimateText = "";
        string _estimateCapped;   // why tiles held at the max factor matter, when the last estimate found some

        const string FoldoutKeyPrefix = "GregoryTerrain.RendererEditor.";

        // The levels' buffers grow after a frame's readback, in Edit Mode too (the Scene view's
        // cameras): the memory readout repaints once each time they change, not every frame. Noted
        // when the repaint is asked for, so a folded or multi-object inspector never loops.
        long _levelBytesAtRepaint;

        void OnEnable() => EditorApplication.update += RepaintWhenLevelMemoryChanges;
        void OnDisable() => EditorApplication.update -= RepaintWhenLevelMemoryChanges;

        void RepaintWhenLevelMemoryChanges()
        {
            var r = target as GregoryTerrainRenderer;
            if (r == null) return;
            long bytes = r.VertexCacheAllocatedBytes;   // a plain sum; LevelCount asks the draw mode
            if (bytes == _levelBytesAtRepaint) return;
            _levelBytesAtRepaint = bytes;
            if (r.LevelCount > 0) Repaint();
        }

        public override void OnInspectorGUI()
        {
            serializedObject.UpdateIfRequiredOrScript();
            FindRangeControllers();
            if (serializedObject.isEditingMultipleObjects)
                EditorGUILayout.HelpBox("Select one renderer to see its triangle counts and warnings.", MessageType.Info);
            else
                DrawReadouts((GregoryTerrainRenderer)target);
            DrawSettings();
            serializedObject.ApplyModifiedProperties();
            if (!serializedObject.isEditingMultipleObjects) PatchGridSculptTool.DrawSettings((GregoryTerrainRenderer)target);
        }

        void DrawReadouts(GregoryTerrainRenderer r)
        {
            EditorGUILayout.LabelField(new GUIContent("Triangles in view", "Triangles drawn for the LOD camera (else the main or Scene view camera) at the current settings. Up to 256 tiles are evaluated."),
                new GUIContent(InViewText(r)));
            if (_estimateCapped != null) EditorGUILayout.HelpBox(_estimateCapped, MessageType.Info);
            EditorGUILayout.LabelField(new GUIContent("Most triangles", "The most triangles these settings can draw, whatever the view (with Horizon levels, every level's tiles)."),
                new GUIContent($"{r.EstimatedTriangleCount:N0} ({r.DrawnTileCount:N0} tiles{(r.LevelCount > 0 ? $" in {r.LevelCount} levels" : "")})"));
            bool cache = r.VertexEvaluation == VertexEvaluation.ComputeCache && r.LevelCount == 0;   // the levels keep their own cache per camera
            if (cache)
                EditorGUILayout.LabelField(new GUIContent("Vertex cache memory", "GPU memory the Compute cache's buffers take at these settings."),
                    new GUIContent(FormatBytes(r.VertexCacheBytes)));
            else if (r.LevelCount > 0)
                EditorGUILayout.LabelField(new GUIContent("Levels' buffer memory", "GPU memory the Horizon levels' buffers use now, for every camera that has drawn them. Each camera has a buffer of tile factors and a vertex buffer that grows with its view, up to 128 MiB."),
                    new GUIContent(FormatBytes(r.VertexCacheAllocatedBytes)));
            if (cache && !SystemInfo.supportsComputeShaders)
                EditorGUILayout.HelpBox("Vertex evaluation is Compute cache, but this GPU has no compute shaders (SystemInfo.supportsComputeShaders is false): the domain stage evaluates the vertices instead.", MessageType.Warning);
            else if (cache && r.VertexCacheFallbackReason != null)
                EditorGUILayout.HelpBox("Compute cache not used: " + r.VertexCacheFallbackReason + ". The domain stage evaluates the vertices.", MessageType.Warning);
            if (r.DrawsFallback)
                EditorGUILayout.HelpBox("The shader's tessellated SubShader is not used on this GPU: the vertex-shader fallback is drawn (fixed grid per tile, Fallback grid factor).", MessageType.Warning);
            if (r.Grid != null && !r.Grid.IsValid)
                EditorGUILayout.HelpBox("Grid: " + r.Grid.ValidationError, MessageType.Error);
            if (r.SettingsError != null)
                EditorGUILayout.HelpBox("Settings: " + r.SettingsError, MessageType.Error);
            if (r.Material == null)
                EditorGUILayout.HelpBox("Assign a material that uses GregoryTerrain/Terrain.", MessageType.Warning);
        }

        // The serialized field paths are the scenes' data: a rename keeps the old field hidden and maps it in
        // FlatSettingsUpgrade.Paths (the load's move, the prefab override upgrade). What shows where: RendererInspectorLayout.
        void DrawSettings()
        {
            var contexts = targets.Select(t => ContextOf((GregoryTerrainRenderer)t)).ToList();
            foreach (var (title, open, fields) in RendererInspectorLayout.Sections)
                Section(title, open, () =>
                {
                    if (title == "Noise and colour") KeywordOffNote(ShaderKeywords.Noise, "Noise detail");
                    foreach (string name in fields)
                    {
                        if (!RendererInspectorLayout.ShowsForAny(name, contexts)) continue;
                        if (name == "heightColor.gamma") KeywordOffNote(ShaderKeywords.HeightColor, "Height colour");
                        DrawField(name);
                    }
                });
        }

        InspectorContext ContextOf(GregoryTerrainRenderer r) => new InspectorContext(ModeOf(r),
            r.UniformFactor == 0, r.VertexEvaluation == VertexEvaluation.ComputeCache, r.DrawsFallback);

        void DrawField(string name)
        {
            if (name == RendererInspectorLayout.ViewModeField) { DrawViewMode(); DrawQuality(); return; }
            foreach (var m in RendererInspectorLayout.MetreFields)
                if (m.field == name && MetresField(m.field, m.kind, m.label, m.min, m.max)) return;
            if (RendererInspectorLayout.Find(name) is SettingField f) SettingsDrawer.DrawField(EditorGUILayout.GetControlRect(), P(name), f);
            else EditorGUILayout.PropertyField(P(name));
        }

        static readonly GUIContent ViewModeLabel = new GUIContent("View mode", "Open world: from each camera's feet to the horizon (Horizon levels). " +
            "Single range: the Range, or a Camera Range Controller's. Zoom: a Zoom Range Controller zooms into a fixed box (Camera Range Controllers turned off).");
        static readonly GUIContent[] ViewModeNames = { new GUIContent("Open world"), new GUIContent("Single range"), new GUIContent("Zoom") };

        // Searched once per Layout event.
        ZoomRangeController[] _zooms;
        CameraRangeController[] _cameraRanges;

        void FindRangeControllers()
        {
            if (Event.current.type != EventType.Layout && _zooms != null) return;
            _zooms = UnityEngine.Object.FindObjectsByType<ZoomRangeController>(FindObjectsSortMode.None);
            _cameraRanges = UnityEngine.Object.FindObjectsByType<CameraRangeController>(FindObjectsSortMode.None);
        }

        TerrainViewMode ModeOf(GregoryTerrainRenderer r) =>
            RendererInspectorLayout.ModeOf(r.HorizonLevels, _zooms.Any(z => z != null && z.enabled && z.Target == r));

        /// <summary>Horizon levels as a view mode; one Undo step.</summary>
        void DrawViewMode()
        {
            SerializedProperty levels = serializedObject.FindProperty(RendererInspectorLayout.ViewModeField);
            TerrainViewMode? mode = RendererInspectorLayout.CommonMode(targets.Select(t => ModeOf((GregoryTerrainRenderer)t)).ToList());
            Rect rect = EditorGUILayout.GetControlRect();
            GUIContent label = EditorGUI.BeginProperty(rect, ViewModeLabel, levels);
            EditorGUI.showMixedValue = mode == null;
            EditorGUI.BeginChangeCheck();
            var chosen = (TerrainViewMode)EditorGUI.Popup(rect, label, mode.HasValue ? (int)mode.Value : -1, ViewModeNames);
            EditorGUI.showMixedValue = false;
            bool changed = EditorGUI.EndChangeCheck();
            EditorGUI.EndProperty();
            if (!changed || chosen < TerrainViewMode.OpenWorld) return;
            Undo.SetCurrentGroupName("View mode " + ViewModeNames[(int)chosen].text);
            int group = Undo.GetCurrentGroup();
            levels.boolValue = chosen == TerrainViewMode.OpenWorld;
            serializedObject.ApplyModifiedProperties();
            foreach (UnityEngine.Object t in targets)
            {
                if (chosen == TerrainViewMode.OpenWorld) MakeTilesOpenWorld(t);
                SetZoomController((GregoryTerrainRenderer)t, chosen == TerrainViewMode.Zoom);
            }
            serializedObject.Update();
            Undo.CollapseUndoOperations(group);
        }

        static void MakeTilesOpenWorld(UnityEngine.Object renderer)
        {
            using var so = new SerializedObject(renderer);
            SerializedProperty tiles = so.FindProperty("tessellation.tiles");
            int open = RendererInspectorLayout.TilesForOpenWorld(tiles.intValue);
            if (open == tiles.intValue) return;
            tiles.intValue = open;
            so.ApplyModifiedProperties();
        }

        /// <summary>Zoom: a controller targeting r enabled (else an empty one on r adopted, else added), its Camera Range Controllers off.</summary>
        void SetZoomController(GregoryTerrainRenderer r, bool on)
        {
            ZoomRangeController[] own = _zooms.Where(z => z != null && z.Target == r).ToArray();
            if (!on)
            {
                foreach (ZoomRangeController z in own) SetSerialized(z, false, null);
                return;
            }
            foreach (CameraRangeController c in _cameraRanges.Where(c => c != null && c.enabled && c.Target == r)) SetSerialized(c, false, null);
            if (own.Length > 0) { SetSerialized(own[0], true, null); return; }
            ZoomRangeController empty = r.GetComponents<ZoomRangeController>().FirstOrDefault(z => z.Target == null);
            if (empty != null) SetSerialized(empty, true, r);
            else Undo.AddComponent<ZoomRangeController>(r.gameObject).Target = r;
        }

        // Not the renderer's fields (RendererInspectorTests reads literals as its).
        const string BehaviourEnabled = "m_Enabled", ControllerTarget = "target";

        // Through a SerializedObject: Undo and the prefab override recorded.
        static void SetSerialized(Behaviour b, bool enabled, GregoryTerrainRenderer newTarget)
        {
            using var so = new SerializedObject(b);
            so.FindProperty(BehaviourEnabled).boolValue = enabled;
            if (newTarget != null) so.FindProperty(ControllerTarget).objectReferenceValue = newTarget;
            so.ApplyModifiedProperties();
        }

        static readonly GUIContent QualityLabel = new GUIContent("Quality", "Sets Target pixel error, Max factor, Tiles, Noise octaves and " +
            "Vertex evaluation: Low 16 px, Medium 8 px (a new terrain's), High 2 px, Ultra 0.5 px (largest error about 1 px; Compute cache if a Cache Shader is set).");
        static readonly GUIContent[] QualityNames = { new GUIContent("Low"), new GUIContent("Medium"), new GUIContent("High"), new GUIContent("Ultra"), new GUIContent("Custom") };

        void DrawQuality()
        {
            SerializedProperty[] p = { P("tessellation.targetPixels"), P("tessellation.maxFactor"), P("tessellation.tiles"), P("noise.octaves"), P("vertexEvaluation") };
            QualityPreset? now = RendererInspectorLayout.PresetOf(new QualityValues(p[0].floatValue, p[1].floatValue, p[2].intValue, p[3].intValue, p[4].intValue));
            EditorGUI.showMixedValue = p.Any(x => x.hasMultipleDifferentValues);
            EditorGUI.BeginChangeCheck();
            int chosen = EditorGUILayout.Popup(QualityLabel, now.HasValue ? (int)now.Value : 4, QualityNames);
            EditorGUI.showMixedValue = false;
            if (!EditorGUI.EndChangeCheck() || chosen == 4) return;
            Undo.SetCurrentGroupName("Quality " + QualityNames[chosen].text);
            QualityValues v = RendererInspectorLayout.Preset((QualityPreset)chosen);
            // Applied with the inspector's other changes at the end of OnInspectorGUI: one Undo step.
            p[0].floatValue = v.targetPixelError; p[1].floatValue = v.maxFactor; p[2].intValue = v.tiles; p[3].intValue = v.noiseOctaves;
            foreach (UnityEngine.Object t in targets)
            {
                var r = (GregoryTerrainRenderer)t;
                int evaluation = RendererInspectorLayout.PresetToWrite((QualityPreset)chosen, new QualityValues(0f, 0f, 0, 0, (int)r.VertexEvaluation),
                    r.CacheShader != null, r.HorizonLevels).vertexEvaluation;
                if (evaluation == (int)r.VertexEvaluation) continue;
                using var so = new SerializedObject(t);
                so.FindProperty("vertexEvaluation").intValue = evaluation;
                so.ApplyModifiedProperties();
            }
        }

        SerializedProperty P(string name) => serializedObject.FindProperty(name);

        /// <summary>A terrain-unit length shown in metres (stored unchanged); false when the selection's scales differ.</summary>
        readonly Dictionary<string, string> _refused = new Dictionary<string, string>();

        bool MetresField(string name, TerrainLength kind, string text, float min, float max)
        {
            Double3 unit = ((GregoryTerrainRenderer)target).WorldUnitsPerObjectUnit;
            if (targets.Any(t => !((GregoryTerrainRenderer)t).WorldUnitsPerObjectUnit.Equals(unit))) return false;
            DrawMetresField(P(name), name, unit, kind, text, min, max, _refused, RendererInspectorLayout.Find(name)?.tooltip);
            return true;
        }

        /// <summary><paramref name="p"/> in metres of a terrain of <paramref name="unit"/> (x: width, y: height scale); a refused value's note kept in <paramref name="refused"/>; <paramref name="tooltip"/>: a settings struct field's (Core has no [Tooltip]), else the field's own.</summary>
        internal static void DrawMetresField(SerializedProperty p, string name, Double3 unit, TerrainLength kind, string text, float min, float max,
            Dictionary<string, string> refused, string tooltip = null)
        {
            Rect rect = EditorGUILayout.GetControlRect();
            GUIContent label = EditorGUI.BeginProperty(rect, new GUIContent(text, $"{tooltip ?? p.tooltip} Stored: {p.floatValue:G4}; it scales with the terrain."), p);
            EditorGUI.showMixedValue = p.hasMultipleDifferentValues;
            EditorGUI.BeginChangeCheck();
            float metres = (float)RendererInspectorLayout.ToMetres(kind, p.floatValue, unit.y, unit.x);
            float typed = kind == TerrainLength.Height
                ? EditorGUI.Slider(rect, label, metres, (float)(min * unit.y), (float)(max * unit.y))
                : EditorGUI.DelayedFloatField(rect, label, metres);   // typing 0.5 passes through 0
            if (EditorGUI.EndChangeCheck())
            {
                string problem = kind == TerrainLength.Height ? null : RendererInspectorLayout.LengthProblem(text, typed);
                if (problem == null) { refused.Remove(name); p.floatValue = RendererInspectorLayout.ClampedFromMetres(kind, typed, unit.y, unit.x, min, max); }
                else refused[name] = problem;
            }
            EditorGUI.showMixedValue = false;
            EditorGUI.EndProperty();
            if (refused.TryGetValue(name, out string note)) EditorGUILayout.HelpBox(note, MessageType.Warning);
        }

        /// <summary>Noise and colour act only with the material's toggle on: still editable, with a note.</summary>
        void KeywordOffNote(string keyword, string toggle)
        {
            if (serializedObject.isEditingMultipleObjects) return;
            Material m = ((GregoryTerrainRenderer)target).Material;
            if (m != null && !m.IsKeywordEnabled(keyword))
                EditorGUILayout.HelpBox($"The material's {toggle} toggle is off: these settings have no effect.", MessageType.Info);
        }

        /// <summary>A foldout whose open state is kept per user.</summary>
        static void Section(string title, bool openByDefault, System.Action drawFields)
        {
            string key = FoldoutKeyPrefix + title;
            bool open = EditorPrefs.GetBool(key, openByDefault);
            bool now = EditorGUILayout.BeginFoldoutHeaderGroup(open, title);
            if (now != open) EditorPrefs.SetBool(key, now);
            if (now)
            {
                EditorGUI.indentLevel++;
                drawFields();
                EditorGUI.indentLevel--;
            }
            EditorGUILayout.EndFoldoutHeaderGroup();
        }

        string InViewText(GregoryTerrainRenderer r)
        {
            if (Event.current.type != EventType.Layout || EditorApplication.timeSinceStartup - _estimateTime < EstimateSeconds) return _estimateText;
            _estimateTime = EditorApplication.timeSinceStartup;
            _estimateCapped = null;
            Camera cam = r.EffectiveLodCamera;
            if (cam == null && SceneView.lastActiveSceneView != null) cam = SceneView.lastActiveSceneView.camera;
            TriangleEstimate? e = cam != null ? r.EstimateTrianglesInView(cam) : null;
            if (cam == null) _estimateText = "no camera";
            else if (e == null) _estimateText = r.DrawsFallback ? "fallback: see Most triangles" : "(nothing drawn yet)";
            else
            {
                TriangleEstimate v = e.Value;
                string sample = v.tilesSampled < v.tileCount ? $", {v.tilesSampled} of {v.tileCount} tiles sampled" : "";
                string levels = r.LevelCount > 0 ? $", {r.LevelCount} levels" : "";
                _estimateText = $"{v.triangles:N0} ({cam.name}: {v.tilesSampledDrawn} of {v.tilesSampled} tiles drawn{sample}{levels})";
                // Tiles held at the max factor may miss the target: more, smaller tiles need smaller factors.
                if (v.tilesSampledAtMaxFactor > 0)
                    _estimateCapped = $"{v.tilesSampledAtMaxFactor} of the {v.tilesSampledDrawn} tiles evaluated and drawn are held at the max factor: the target pixel error may not hold there. More tiles need smaller factors.";
            }
            return _estimateText;
        }

        /// <summary>"18,591,744 bytes (17.7 MiB)".</summary>
        static string FormatBytes(long bytes) =>
            bytes.ToString("N0") + " bytes (" + (bytes / (1024.0 * 1024.0)).ToString("0.0") + " MiB)";

        // F frames the drawn terrain (Unity calls these by name; a MonoBehaviour has no bounds): every
        // selected renderer that has drawn; if none has, Unity frames the selection itself.
        bool HasFrameBounds() => targets.Any(t => Drawn(t as GregoryTerrainRenderer));

        Bounds OnGetFrameBounds()
        {
            Bounds? all = null;
            foreach (UnityEngine.Object t in targets)
            {
                var r = t as GregoryTerrainRenderer;
                if (!Drawn(r)) continue;
                Bounds b = r.WorldBounds();
                if (all is Bounds a) { a.Encapsulate(b); all = a; }
                else all = b;
            }
            return all ?? default;
        }

        static bool Drawn(GregoryTerrainRenderer r) => r != null && r.isActiveAndEnabled && r.HasDrawn;

        void OnSceneGUI()
        {
            var r = (GregoryTerrainRenderer)target;
            PatchGridAsset grid = r.Grid;
            if (grid == null || !grid.IsValid || !TerrainScenePoints.TryGet(r, out TerrainScenePoints points)) return;
            Handles.matrix = Matrix4x4.identity;   // world positions, from the renderer's frame
            if (r.debugShowPatchWireframe) DrawWireframe(grid, points);
            if (r.debugShowControlPoints) EditControlPoints(r, grid, points);
        }

        static void DrawWireframe(PatchGridAsset grid, TerrainScenePoints points)
        {
            Handles.color = Color.cyan;
            for (int p = 0; p < grid.PatchCount; p++)
            {
                // The four boundary curves' control polygons (slots 0-3, 12-15, 0-12, 3-15).
                for (int k = 0; k < 3; k++)
                {
                    Line(grid, points, p, k, k + 1);
                    Line(grid, points, p, 12 + k, 13 + k);
                    Line(grid, points, p, 4 * k, 4 * k + 4);
                    Line(grid, points, p, 4 * k + 3, 4 * k + 7);
                }
            }
        }

        static void Line(PatchGridAsset grid, TerrainScenePoints points, int p, int a, int b) =>
            Handles.DrawLine(points.ToWorld(grid.GetControlPoint(p, a)), points.ToWorld(grid.GetControlPoint(p, b)));

        /// <summary>Buttons for the chosen patch and its 8 neighbours only (180 at most); a click on the terrain chooses the patch, on a button the point.</summary>
        void EditControlPoints(GregoryTerrainRenderer r, PatchGridAsset grid, TerrainScenePoints points)
        {
            if (_nearPatch >= grid.PatchCount) _nearPatch = -1;
            if (_nearPatch >= 0)
            {
                int ci = _nearPatch % grid.Columns, cj = _nearPatch / grid.Columns;
                for (int j = Math.Max(0, cj - 1); j <= Math.Min(grid.Rows - 1, cj + 1); j++)
                for (int i = Math.Max(0, ci - 1); i <= Math.Min(grid.Columns - 1, ci + 1); i++)
                for (int s = 0; s < GregoryPatch.SlotCount; s++)
                {
                    int p = j * grid.Columns + i;
                    Vector3 pos = points.ToWorld(grid.GetControlPoint(p, s));
                    float size = 0.06f * HandleUtility.GetHandleSize(pos);
                    Handles.color = s >= 16 ? Color.yellow : Color.white;
                    if (Handles.Button(pos, Quaternion.identity, size, size, Handles.DotHandleCap))
                    {
                        _selectedPatch = p; _selectedSlot = s;
                    }
                }
            }
            if (_selectedPatch >= 0 && _selectedPatch < grid.PatchCount)
            {
                Vector3 current = points.ToWorld(grid.GetControlPoint(_selectedPatch, _selectedSlot));
                EditorGUI.BeginChangeCheck();
                Vector3 moved = Handles.PositionHandle(current, Quaternion.identity);
                if (EditorGUI.EndChangeCheck())
                {
                    PatchGridAssetUndo.MoveControlPoint(grid, _selectedPatch, _selectedSlot, points.ToTerrain(moved));
                }
            }
            PickPatchUnderMouse(r, grid);
        }

        // After the handles: only a click on bare terrain picks a patch, none while the sculpt tool paints.
        void PickPatchUnderMouse(GregoryTerrainRenderer r, PatchGridAsset grid)
        {
            Event e = Event.current;
            if (e.type == EventType.MouseDown && e.button == 0 && !e.alt && GUIUtility.hotControl == 0 &&
                UnityEditor.EditorTools.ToolManager.activeToolType != typeof(PatchGridSculptTool) &&
                r.Raycast(HandleUtility.GUIPointToWorldRay(e.mousePosition), float.PositiveInfinity, out Vector3 hit, out _, out _))
            {
                Double3 local = r.WorldToTerrainObject(hit);   // object (x, height, y)
                _nearPatch = grid.FindPatch(local.x, local.z);
                e.Use();
            }
        }
    }
}
