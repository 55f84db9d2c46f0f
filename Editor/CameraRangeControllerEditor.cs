using System.Collections.Generic;
using System.Linq;
using UnityEditor;

namespace GregoryTerrain.EditorTools
{
    /// <summary>View distance in metres of the target's width; stored as a part of it, so saved scenes keep their square.</summary>
    [CustomEditor(typeof(CameraRangeController)), CanEditMultipleObjects]
    internal sealed class CameraRangeControllerEditor : Editor
    {
        readonly Dictionary<string, string> _refused = new Dictionary<string, string>();

        static bool SameWidth(GregoryTerrainRenderer a, GregoryTerrainRenderer b) =>
            a != null && a.WorldUnitsPerObjectUnit.Equals(b.WorldUnitsPerObjectUnit);

        public override void OnInspectorGUI()
        {
            serializedObject.Update();
            using (new EditorGUI.DisabledScope(true))
                EditorGUILayout.PropertyField(serializedObject.FindProperty("m_Script"));   // as the default inspector draws it
            EditorGUILayout.PropertyField(serializedObject.FindProperty("target"));
            EditorGUILayout.PropertyField(serializedObject.FindProperty("followCamera"));
            var f = RendererInspectorLayout.ViewDistanceField;
            SerializedProperty p = serializedObject.FindProperty(f.field);
            GregoryTerrainRenderer r = ((CameraRangeController)target).Target;
            // Unity's == , not a C# pattern: an empty or deleted reference is a fake-null object in the Editor.
            if (r != null && targets.All(t => SameWidth(((CameraRangeController)t).Target, r)))
                GregoryTerrainRendererEditor.DrawMetresField(p, f.field, r.WorldUnitsPerObjectUnit, f.kind, f.label, f.min, f.max, _refused);
            else EditorGUILayout.PropertyField(p);   // no terrain, or terrains of different widths: the part of the width
            EditorGUILayout.PropertyField(serializedObject.FindProperty("lookAhead"));
            serializedObject.ApplyModifiedProperties();
        }
    }
}
