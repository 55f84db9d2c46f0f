// STUB members of UnityEditor used by the editor tools' fixes for issue 36 (the sculpt shortcut's
// guard, the Scene view's notification), kept apart so that changes elsewhere merge cleanly. Checked
// against UnityCsReference 2022.3: Editor/Mono/Selection.bindings.cs, Editor/Mono/EditorWindow.cs.
// SR:<Page> as in UnityEditor.cs. NOT Unity's assembly: signatures only.
#pragma warning disable CS1591
using UnityEngine;

namespace UnityEditor
{
    public sealed partial class Selection
    {
        public static GameObject[] gameObjects => null;                                      // SR:Selection-gameObjects (read only)
    }

    public partial class EditorWindow
    {
        public void ShowNotification(GUIContent notification) { }                            // SR:EditorWindow.ShowNotification
    }
}
