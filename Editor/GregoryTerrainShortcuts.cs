using System;
using GregoryTerrain;
using UnityEditor;
using UnityEditor.ShortcutManagement;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// The Scene view's Gregory Terrain keys, rebindable in Unity's Shortcut Manager (Edit > Shortcuts,
    /// "Gregory Terrain"). Active while a Scene view has focus, on the selected terrains (none: nothing).
    /// The defaults clash with no Unity 2022.3 default in the Scene view or global contexts
    /// (ShortcutClashTests).
    /// </summary>
    static class GregoryTerrainShortcuts
    {
        [Shortcut("Gregory Terrain/Toggle Control Points", typeof(SceneView), KeyCode.G)]
        static void ToggleControlPoints() =>
            ChangeSelected("Toggle control points", r => r.debugShowControlPoints = !r.debugShowControlPoints);

        [Shortcut("Gregory Terrain/Toggle Patch Wireframe", typeof(SceneView), KeyCode.G, ShortcutModifiers.Shift)]
        static void ToggleWireframe() =>
            ChangeSelected("Toggle patch wireframe", r => r.debugShowPatchWireframe = !r.debugShowPatchWireframe);

        [Shortcut("Gregory Terrain/Uniform Factor Down", typeof(SceneView), KeyCode.U)]
        static void FactorDown() => ChangeSelected("Uniform factor -", r => r.UniformFactor = r.UniformFactor - 1);

        [Shortcut("Gregory Terrain/Uniform Factor Up", typeof(SceneView), KeyCode.I)]
        static void FactorUp() => ChangeSelected("Uniform factor +", r => r.UniformFactor = r.UniformFactor + 1);

        [Shortcut("Gregory Terrain/Sculpt Tool", typeof(SceneView), KeyCode.B)]
        static void SculptTool()
        {
            // ToolManager.SetActiveTool throws InvalidOperationException when the selection has no
            // terrain for the tool: check first and do nothing, as Unity's own tool shortcuts do.
            if (!SculptToolAvailable())
            {
                SceneView.lastActiveSceneView?.ShowNotification(new GUIContent("Select a Gregory terrain to sculpt it."));
                return;
            }
            UnityEditor.EditorTools.ToolManager.SetActiveTool<PatchGridSculptTool>();
        }

        /// <summary>
        /// Whether Unity has made the sculpt tool for the selection: only for components the Inspector
        /// shows, which with several GameObjects selected are those all of them have.
        /// </summary>
        static bool SculptToolAvailable()
        {
            GameObject[] selected = Selection.gameObjects;
            // Unity makes no component tool for assets (a prefab picked in the Project window), and
            // builds tools from the Inspector's editors, so a selection holding anything else has none.
            return selected.Length > 0 && Selection.objects.Length == selected.Length &&
                   Array.TrueForAll(selected, g => !EditorUtility.IsPersistent(g) && g.GetComponent<GregoryTerrainRenderer>() != null);
        }

        [Shortcut("Gregory Terrain/Shrink Sculpt Brush", typeof(SceneView), KeyCode.LeftBracket, ShortcutModifiers.Shift)]
        static void ShrinkBrush() => PatchGridSculptTool.ScaleBrush(1f / 1.2f);

        [Shortcut("Gregory Terrain/Grow Sculpt Brush", typeof(SceneView), KeyCode.RightBracket, ShortcutModifiers.Shift)]
        static void GrowBrush() => PatchGridSculptTool.ScaleBrush(1.2f);

        /// <summary>One undo step over every selected, editable terrain; nothing when none is selected.</summary>
        static void ChangeSelected(string undoName, Action<GregoryTerrainRenderer> change)
        {
            GregoryTerrainRenderer[] selected = Selection.GetFiltered<GregoryTerrainRenderer>(SelectionMode.Editable);
            if (selected.Length == 0) return;
            Undo.RecordObjects(selected, undoName);
            foreach (GregoryTerrainRenderer r in selected) change(r);
            SceneView.RepaintAll();
        }
    }
}
