using System;
using System.Threading;
using GregoryTerrain;
using UnityEditor;
using UnityEditor.EditorTools;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>What the sculpt tool's left mouse button does.</summary>
    internal enum SculptMode
    {
        /// <summary>Raise the ground under the brush (hold Shift to lower it).</summary>
        Raise,
        /// <summary>Lower the ground under the brush (hold Shift to raise it).</summary>
        Lower,
        /// <summary>Even out bumps under the brush.</summary>
        Smooth,
        /// <summary>Pull the ground toward the height where the stroke started.</summary>
        Flatten,
        /// <summary>Drag over the terrain to select a rectangle of patches.</summary>
        SelectPatches,
    }

    /// <summary>
    /// The Scene-view sculpt tool, as Unity's Terrain tools work: the brush disc follows the surface,
    /// a left drag paints a stroke of dabs (Core's PatchBrush, G1 kept), one undo step a stroke.
    /// SelectPatches drags a patch rectangle that confines the brush and that "Refit selection" refits.
    /// Settings live in the renderer's inspector.
    /// </summary>
    [EditorTool("Sculpt Gregory Terrain", typeof(GregoryTerrainRenderer))]
    internal sealed class PatchGridSculptTool : EditorTool
    {
        internal static SculptMode Mode = SculptMode.Raise;
        /// <summary>Brush radius in metres (world units along the terrain's x), as typed; dabs use at least the control-point spacing (<see cref="BrushRadius"/>).</summary>
        internal static float RadiusMetres = (float)NewTerrainAuthoring.DefaultBrushMetres;
        /// <summary>Patches a side the Resample button makes.</summary>
        internal static int ResampleSide = NewTerrainAuthoring.Patches;
        static string s_ResampleMessage;
        static MessageType s_ResampleMessageType;
        static PatchGridAsset s_ResampleMessageGrid;   // the message is shown under that grid's renderers only
        /// <summary>Raise/lower: metres added at the brush centre per dab.</summary>
        internal static float HeightMetres = 1f;
        /// <summary>Smooth/flatten: fraction of the way per dab at the centre.</summary>
        internal static float Amount = 0.5f;
        /// <summary>Whether the selection confines the brush.</summary>
        internal static bool BrushInsideSelection = true;

        /// <summary>The selected patches and the grid they belong to (cleared when the grid changes shape).</summary>
        internal static PatchGridAsset SelectionGrid;
        internal static PatchRect Selection;

        static readonly GUIContent Icon = new GUIContent("Sculpt", "Sculpt the Gregory terrain: raise, lower, smooth or flatten with a brush, or select patches.");

        const string StrokeName = "Sculpt Gregory terrain";
        int _undoGroup = -1;
        bool _stroking;
        // Core's grid, kept between strokes while the asset's version matches (no whole-grid copy a
        // stroke); its patches are never shared with the renderer's grids.
        PatchGrid _strokeGrid;
        PatchGridAsset _strokeAsset;
        int _strokeVersion;
        Vector3 _lastDab;
        double _flattenTarget;
        int _selectFrom = -1;
        int _dragControl;               // the control ID holding GUIUtility.hotControl during a drag, else 0
        static readonly int ControlHint = "GregoryTerrainSculptTool".GetHashCode();

        public override GUIContent toolbarIcon => Icon;

        static readonly GUIContent ModeLabel = new GUIContent("Sculpt mode", "What a left drag on the terrain does. Shift swaps raise and lower.");
        static readonly GUIContent RadiusLabel = new GUIContent("Brush radius (m)", "Size of the brush in metres. Keys Shift+[ and Shift+] shrink and grow it.");
        static readonly GUIContent HeightLabel = new GUIContent("Height per dab (m)", "How far one dab raises or lowers the ground at the brush centre, in metres.");
        static readonly GUIContent AmountLabel = new GUIContent("Strength", "How far one dab moves the ground toward smooth or flat at the brush centre: 0 nothing, 1 all the way.");
        static readonly GUIContent InsideLabel = new GUIContent("Only inside selection", "Keep the brush inside the selected patches; points just outside may still move so the surface stays smooth.");
        static readonly GUIContent SpacingLabel = new GUIContent("Control-point spacing (m)", "Metres between neighbouring control points (the widest patch / 3). A brush smaller than this may miss every point, so it is used at this size at least.");
        static readonly GUIContent ResampleSideLabel = new GUIContent("Resample to N x N", "Patches a side of the resampled grid (1 to 1024). More patches: control points closer together, a finer brush.");
        static readonly GUIContent ResampleLabel = new GUIContent("Resample grid", "Replace the grid with N x N patches fitted to the current surface (it keeps its shape; the error is reported). One undo step; Cancel leaves the grid as it was.");
        static readonly GUIContent ClearLabel = new GUIContent("Clear selection", "Forget the selected patches.");

        /// <summary>The tool's settings, shown in the renderer's inspector.</summary>
        internal static void DrawSettings(GregoryTerrainRenderer renderer)
        {
            EditorGUILayout.Space();
            EditorGUILayout.HelpBox("Sculpt: pick the Sculpt tool in the Scene view's Tools overlay (key B), then drag on the terrain. Each stroke is one undo step.", MessageType.None);
            Mode = (SculptMode)EditorGUILayout.EnumPopup(ModeLabel, Mode);
            double spacing = ControlPointSpacing(renderer);
            if (!double.IsNaN(spacing)) EditorGUILayout.LabelField(SpacingLabel, new GUIContent($"{spacing:G3}"));
            RadiusMetres = Mathf.Max(1e-3f, EditorGUILayout.FloatField(RadiusLabel, RadiusMetres));
            if (Mode != SculptMode.SelectPatches && RadiusMetres < spacing)
                EditorGUILayout.HelpBox($"The brush ({RadiusMetres:G3} m) is smaller than the control-point spacing ({spacing:G3} m), so it is used at {spacing:G3} m. Resample the grid to more patches below to sculpt finer.", MessageType.Warning);
            if (Mode == SculptMode.Raise || Mode == SculptMode.Lower)
                HeightMetres = Mathf.Max(0f, EditorGUILayout.FloatField(HeightLabel, HeightMetres));
            else if (Mode != SculptMode.SelectPatches)
                Amount = EditorGUILayout.Slider(AmountLabel, Amount, 0f, 1f);
            BrushInsideSelection = EditorGUILayout.Toggle(InsideLabel, BrushInsideSelection);
            if (SelectionGrid != null)
            {
                EditorGUILayout.LabelField("Selection", $"columns {Selection.I0} to {Selection.I1}, rows {Selection.J0} to {Selection.J1} of '{SelectionGrid.name}'");
                if (GUILayout.Button(ClearLabel)) { SelectionGrid = null; SceneView.RepaintAll(); }
            }
            ResampleSide = Mathf.Clamp(EditorGUILayout.IntField(ResampleSideLabel, ResampleSide), 1, PatchGridWindow.MaxSide);
            using (new EditorGUI.DisabledScope(renderer == null || renderer.Grid == null || !renderer.Grid.IsValid))
                if (GUILayout.Button(ResampleLabel)) { Resample(renderer, ResampleSide); GUIUtility.ExitGUI(); }
            if (s_ResampleMessage != null && s_ResampleMessageGrid == renderer.Grid) EditorGUILayout.HelpBox(s_ResampleMessage, s_ResampleMessageType);
        }

        /// <summary>Metres between neighbouring control points of the renderer's grid (Terrain Size and the Transform included); NaN without a valid grid.</summary>
        internal static double ControlPointSpacing(GregoryTerrainRenderer renderer)
        {
            PatchGridAsset grid = renderer != null ? renderer.Grid : null;
            if (grid == null || !grid.IsValid) return double.NaN;
            Double3 scale = renderer.WorldUnitsPerObjectUnit;   // object (x, height, y)
            if (!(scale.x > 0) || !(scale.z > 0)) return double.NaN;
            return NewTerrainAuthoring.ControlPointSpacing(grid.XLinesData, grid.YLinesData, scale.x, scale.z);
        }

        /// <summary>The radius a dab uses, metres: the typed one, at least the control-point spacing.</summary>
        internal static float BrushRadius(GregoryTerrainRenderer renderer)
        {
            double spacing = ControlPointSpacing(renderer);
            return double.IsNaN(spacing) ? RadiusMetres : (float)NewTerrainAuthoring.ClampBrushRadius(RadiusMetres, spacing);
        }

        /// <summary>
        /// Refits the grid to <paramref name="side"/> x <paramref name="side"/> patches of its own surface,
        /// with progress and Cancel; one undo step; a cancel or an error leaves the grid as it was.
        /// </summary>
        static void Resample(GregoryTerrainRenderer renderer, int side)
        {
            PatchGridAsset grid = renderer.Grid;
            string name = $"Resample grid to {side} x {side}";
            using var cancel = new CancellationTokenSource();
            var progress = new CancelableProgressBar($"{name}: '{grid.name}'", cancel);
            try
            {
                HeightmapFit fit = ResampleAuthoring.Resample(grid.ToPatchGrid(), side, side, progress, cancel.Token);
                PatchGridAssetUndo.SetGrid(grid, fit.Grid, name);
                if (SelectionGrid == grid) SelectionGrid = null;   // its patch indices name other places on the new grid
                double metres = renderer.WorldUnitsPerObjectUnit.y;
                ReportResample(grid, $"{name}: done. Against the old surface: max error {fit.MaxError * metres:G3} m, RMS {fit.RmsError * metres:G3} m; control points now {ControlPointSpacing(renderer):G3} m apart.", MessageType.Info);
            }
            catch (OperationCanceledException) { ReportResample(grid, $"{name} cancelled; the grid was not changed.", MessageType.Warning); }
            catch (ArgumentException e) { ReportResample(grid, $"{name}: {e.Message} The grid was not changed.", MessageType.Error); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        static void ReportResample(PatchGridAsset grid, string message, MessageType type) { s_ResampleMessage = message; s_ResampleMessageType = type; s_ResampleMessageGrid = grid; }

        /// <summary>Grows or shrinks the brush by a fifth (the shortcuts).</summary>
        internal static void ScaleBrush(float factor)
        {
            RadiusMetres = Mathf.Max(1e-3f, RadiusMetres * factor);
            SceneView.RepaintAll();
        }

        /// <summary>The selection when it belongs to <paramref name="grid"/> and fits its shape.</summary>
        internal static PatchRect? SelectionOf(PatchGridAsset grid)
        {
            if (grid == null || SelectionGrid != grid) return null;
            if (Selection.I1 >= grid.Columns || Selection.J1 >= grid.Rows) return null;
            return Selection;
        }

        public override void OnWillBeDeactivated() => EndDrag();

        public override void OnToolGUI(EditorWindow window)
        {
            Event e = Event.current;
            int id = GUIUtility.GetControlID(ControlHint, FocusType.Passive);
            // Holding the hot control, the tool gets the drag and release outside the Scene view too.
            EventType type = e.GetTypeForControl(id);
            if (type == EventType.MouseUp && GUIUtility.hotControl == id && e.button == 0)
            {
                EndDrag();   // before anything that may return early: the undo group and the mouse are always released
                e.Use();
                return;
            }
            if (!(window is SceneView)) return;
            var renderer = target as GregoryTerrainRenderer;
            if (renderer == null) return;
            PatchGridAsset grid = renderer.Grid;
            if (grid == null || !grid.IsValid) return;
            if (type == EventType.Layout) HandleUtility.AddDefaultControl(id);   // clicks paint instead of selecting other objects

            DrawSelection(renderer, grid);
            Ray ray = HandleUtility.GUIPointToWorldRay(e.mousePosition);
            bool hit = renderer.Raycast(ray, float.PositiveInfinity, out Vector3 point, out Vector3 normal, out _);
            if (hit && type == EventType.Repaint && Mode != SculptMode.SelectPatches)
            {
                Handles.matrix = Matrix4x4.identity;   // the disc is in world space
                Handles.color = Mode == SculptMode.Smooth ? Color.cyan : Mode == SculptMode.Flatten ? Color.yellow : (Mode == SculptMode.Lower) != e.shift ? Color.red : Color.green;
                float radius = BrushRadius(renderer);
                Handles.DrawWireDisc(point, normal, radius);
                Handles.DrawWireDisc(point, normal, 0.5f * radius);
            }

            switch (type)
            {
                case EventType.MouseMove:
                    HandleUtility.Repaint();
                    break;
                // Another control (a handle, the camera) owns the mouse or is nearer: leave its click alone.
                case EventType.MouseDown when e.button == 0 && !e.alt && hit && GUIUtility.hotControl == 0 && HandleUtility.nearestControl == id:
                    GUIUtility.hotControl = _dragControl = id;   // the drag and the release come here, wherever the mouse goes
                    if (Mode == SculptMode.SelectPatches) _selectFrom = PatchUnder(renderer, grid, point);
                    else BeginStroke(renderer, grid, point);
                    Select(renderer, grid, point);
                    e.Use();
                    break;
                case EventType.MouseDrag when GUIUtility.hotControl == id:
                    if (hit)
                    {
                        if (_stroking && Distance(point, _lastDab) >= 0.25f * BrushRadius(renderer)) Dab(renderer, grid, point, e.shift);
                        Select(renderer, grid, point);
                    }
                    e.Use();
                    break;
            }
        }

        /// <summary>Closes the stroke's undo group, ends a selection drag and gives the mouse back.</summary>
        void EndDrag()
        {
            EndStroke();
            _selectFrom = -1;
            if (_dragControl != 0 && GUIUtility.hotControl == _dragControl) GUIUtility.hotControl = 0;
            _dragControl = 0;
        }

        void BeginStroke(GregoryTerrainRenderer renderer, PatchGridAsset grid, Vector3 point)
        {
            Undo.IncrementCurrentGroup();
            Undo.SetCurrentGroupName(StrokeName);
            _undoGroup = Undo.GetCurrentGroup();
            PatchGridAssetUndo.MoveLegacyDataToBlocks(grid, StrokeName);
            if (_strokeAsset != grid || _strokeVersion != grid.Version || _strokeGrid == null)
            {
                _strokeGrid = grid.ToPatchGrid();
                _strokeAsset = grid;
                _strokeVersion = grid.Version;
            }
            _stroking = true;
            _flattenTarget = (float)renderer.WorldToTerrainObject(point).y;   // object y is terrain height z
            Dab(renderer, grid, point, Event.current.shift);
        }

        void Dab(GregoryTerrainRenderer renderer, PatchGridAsset grid, Vector3 point, bool invert)
        {
            _lastDab = point;
            Double3 o = renderer.WorldToTerrainObject(point);
            Vector3 local = new Vector3((float)o.x, (float)o.y, (float)o.z);
            Double3 scale = renderer.WorldUnitsPerObjectUnit;   // Terrain Size, Height Scale and the Transform
            float sx = Mathf.Max((float)scale.x, 1e-12f), sy = Mathf.Max((float)scale.y, 1e-12f);
            bool lower = (Mode == SculptMode.Lower) != invert;
            float radius = BrushRadius(renderer) / sx;
            BrushDab dab = Mode switch
            {
                SculptMode.Smooth => new BrushDab(BrushMode.Smooth, local.x, local.z, radius, Amount),
                SculptMode.Flatten => new BrushDab(BrushMode.Flatten, local.x, local.z, radius, Amount, _flattenTarget),
                _ => new BrushDab(BrushMode.Raise, local.x, local.z, radius, (lower ? -HeightMetres : HeightMetres) / sy),
            };
            try
            {
                PatchEdit edit = PatchBrush.Apply(_strokeGrid, dab, BrushInsideSelection ? SelectionOf(grid) : null);
                PatchGridAssetUndo.ApplyEdit(grid, edit, StrokeName);
                edit.ApplyTo(_strokeGrid);
                _strokeVersion = grid.Version;
            }
            catch (ArgumentException ex)
            {
                Debug.LogWarning($"Sculpt: {ex.Message} The grid was not changed by this dab.", grid);
                EndStroke();
            }
        }

        void EndStroke()
        {
            if (_undoGroup >= 0) Undo.CollapseUndoOperations(_undoGroup);
            _undoGroup = -1;
            _stroking = false;
        }

        void Select(GregoryTerrainRenderer renderer, PatchGridAsset grid, Vector3 point)
        {
            if (Mode != SculptMode.SelectPatches || _selectFrom < 0) return;
            int to = PatchUnder(renderer, grid, point);
            SelectionGrid = grid;
            Selection = PatchRect.Spanning(_selectFrom % grid.Columns, _selectFrom / grid.Columns, to % grid.Columns, to / grid.Columns);
        }

        static int PatchUnder(GregoryTerrainRenderer renderer, PatchGridAsset grid, Vector3 point)
        {
            Double3 local = renderer.WorldToTerrainObject(point);   // object (x, height, y)
            return grid.FindPatch(local.x, local.z);
        }

        static float Distance(Vector3 a, Vector3 b)
        {
            float dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
            return (float)Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        /// <summary>The selection's outline along the boundary control points of its border patches.</summary>
        static void DrawSelection(GregoryTerrainRenderer renderer, PatchGridAsset grid)
        {
            if (Event.current.type != EventType.Repaint || !(SelectionOf(grid) is PatchRect s)) return;
            if (!TerrainScenePoints.TryGet(renderer, out TerrainScenePoints points)) return;
            Handles.matrix = Matrix4x4.identity;   // world positions, from the renderer's frame
            Handles.color = Color.yellow;
            for (int i = s.I0; i <= s.I1; i++)
            {
                Edge(grid, points, s.J0 * grid.Columns + i, 0, 4);
                Edge(grid, points, s.J1 * grid.Columns + i, 3, 4);
            }
            for (int j = s.J0; j <= s.J1; j++)
            {
                Edge(grid, points, j * grid.Columns + s.I0, 0, 1);
                Edge(grid, points, j * grid.Columns + s.I1, 12, 1);
            }
        }

        static void Edge(PatchGridAsset grid, TerrainScenePoints points, int patch, int first, int step)
        {
            for (int k = 0; k < 3; k++)
                Handles.DrawLine(points.ToWorld(grid.GetControlPoint(patch, first + k * step)), points.ToWorld(grid.GetControlPoint(patch, first + (k + 1) * step)));
        }
    }
}
