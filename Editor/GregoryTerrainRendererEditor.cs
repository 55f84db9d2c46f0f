using System;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Renderer inspector: readouts (triangles in view and at most, vertex cache memory), help boxes for
    /// invalid settings and fallbacks, then the settings in foldouts (open state kept per user in
    /// EditorPrefs), each field shown only where it has an effect. Scene-view tools: control points and
    /// patch wireframe drawn with Handles, control points moved with position handles (undoable).
    /// The Scene-view keys are shortcuts of the Shortcut Manager (GregoryTerrainShortcuts).
    /// </summary>
    [CustomEditor(typeof(GregoryTerrainRenderer)), CanEditMultipleObjects]
    internal sealed class GregoryTerrainRendererEditor : Editor
    {
        int _selectedPatch = -1, _selectedSlot = -1;
        int _nearPatch = -1;   // the patch whose neighbourhood shows control-point buttons
        // The in-view estimate evaluates up to 256 tiles' surface samples on the CPU: at most every
        // EstimateSeconds, on Layout events, not on each of the inspector's many GUI events.
        const double EstimateSeconds = 0.25;
        double _estimateTime = double.NegativeInfinity;
        string _estimateText = "";
        string _estimateCapped;   // why tiles held at the max factor matter, when the last estimate found some

        const string FoldoutKeyPrefix = "GregoryTerrain.RendererEditor.";

        public override void OnInspectorGUI()
        {
            serializedObject.UpdateIfRequiredOrScript();
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
            EditorGUILayout.LabelField(new GUIContent("Most triangles", "The most triangles these settings can draw, whatever the view."),
                new GUIContent(r.EstimatedTriangleCount.ToString("N0")));
            bool cache = r.VertexEvaluation == VertexEvaluation.ComputeCache;
            if (cache)
                EditorGUILayout.LabelField(new GUIContent("Vertex cache memory", "GPU memory the Compute cache's buffers take at these settings."),
                    new GUIContent(FormatBytes(r.VertexCacheBytes)));
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

        // The serialized field names are the scenes' data: never rename them here or in the renderer.
        void DrawSettings()
        {
            SerializedProperty uniformFactor = serializedObject.FindProperty("uniformFactor");
            SerializedProperty vertexEvaluation = serializedObject.FindProperty("vertexEvaluation");
            // With several renderers selected and differing values, show what any of them may use.
            bool mayAdapt = uniformFactor.hasMultipleDifferentValues || uniformFactor.intValue == 0;
            bool mayCache = vertexEvaluation.hasMultipleDifferentValues ||
                            vertexEvaluation.intValue == (int)VertexEvaluation.ComputeCache;

            Section("Content", true, () => Fields("grid", "material", "terrainSize", "heightScale", "range"));
            Section("Tessellation", true, () =>
            {
                Fields("tiles", "uniformFactor", "horizonLevels");
                if (mayAdapt) Fields("maxFactor", "targetPixelError", "anchorTiles");
                Fields("fallbackGridFactor");
            });
            Section("Vertex evaluation", true, () =>
            {
                Fields("vertexEvaluation");
                if (mayCache) Fields("cacheShader", "lodCamera");
            });
            Section("Noise and colour", false, () =>
            {
                KeywordOffNote(ShaderIds.NoiseKeyword, "Noise detail");
                Fields("noiseAmplitude", "noiseFrequency", "noiseAlpha", "noiseBeta", "noiseOctaves", "noiseVerticesAcross");
                KeywordOffNote(ShaderIds.HeightColorKeyword, "Height colour");
                Fields("colorGamma", "colorNoiseAmplitude", "colorNoiseFrequency", "colorLow", "colorHigh");
            });
            Section("Lighting", false, () => Fields("shadowCasting", "receiveShadows"));
            Section("Debug", false, () => Fields("debugShowControlPoints", "debugShowPatchWireframe"));
        }

        void Fields(params string[] names)
        {
            foreach (string name in names)
                EditorGUILayout.PropertyField(serializedObject.FindProperty(name));
        }

        /// <summary>
        /// The noise and colour fields act only where the material's toggle is on; they stay editable
        /// (settings kept for when it is turned on), with a note when it is off.
        /// </summary>
        void KeywordOffNote(string keyword, string toggle)
        {
            if (serializedObject.isEditingMultipleObjects) return;
            Material m = ((GregoryTerrainRenderer)target).Material;
            if (m != null && !m.IsKeywordEnabled(keyword))
                EditorGUILayout.HelpBox($"The material's {toggle} toggle is off: these settings have no effect.", MessageType.Info);
        }

        /// <summary>A foldout header whose open state is kept per user across sessions, like Unity's own inspectors.</summary>
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
                _estimateText = $"{v.triangles:N0} ({cam.name}: {v.tilesSampledDrawn} of {v.tilesSampled} tiles drawn{sample})";
                // Tiles held at the max factor may miss the target: more, smaller tiles need smaller factors.
                if (v.tilesSampledAtMaxFactor > 0)
                    _estimateCapped = $"{v.tilesSampledAtMaxFactor} of the {v.tilesSampledDrawn} tiles evaluated and drawn are held at the max factor: the target pixel error may not hold there. More tiles (Tiles M) need smaller factors; fewer, larger tiles draw the same triangles faster until they reach it.";
            }
            return _estimateText;
        }

        /// <summary>"18,591,744 bytes (17.7 MiB)".</summary>
        static string FormatBytes(long bytes) =>
            bytes.ToString("N0") + " bytes (" + (bytes / (1024.0 * 1024.0)).ToString("0.0") + " MiB)";

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

        /// <summary>
        /// Buttons for the control points of the chosen patch and its eight neighbours only (180 at
        /// most, not 20 for every patch of the grid): a click on the terrain chooses the patch under
        /// the mouse, a click on a button picks that point for the move handle.
        /// </summary>
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

        // After the handles: a click that a handle or button took (it holds the hot control, or used
        // the event) is theirs; only a click on bare terrain picks the patch there, and none while
        // the sculpt tool (whose OnToolGUI runs after this) paints.
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
