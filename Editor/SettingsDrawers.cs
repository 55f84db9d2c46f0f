using System.Linq;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>A Core settings struct: a foldout of SettingFields' sliders, and Validate's message while it refuses the values.</summary>
    internal abstract class SettingsDrawer : PropertyDrawer
    {
        const int HelpBoxLines = 2;

        static float Line => EditorGUIUtility.singleLineHeight + EditorGUIUtility.standardVerticalSpacing;

        // No per-property state: Unity shares one drawer among an array's elements and may ask the
        // heights of all of them before drawing any (ReorderableList), so each call validates its own.
        readonly SettingField[] _fields;

        protected SettingsDrawer(SettingField[] fields) => _fields = fields;

        public override float GetPropertyHeight(SerializedProperty property, GUIContent label)
        {
            if (!property.isExpanded) return EditorGUIUtility.singleLineHeight;
            int lines = 1 + _fields.Length + (Problem(property) != null ? HelpBoxLines : 0);
            return lines * Line - EditorGUIUtility.standardVerticalSpacing;
        }

        public override void OnGUI(Rect position, SerializedProperty property, GUIContent label)
        {
            var row = new Rect(position.x, position.y, position.width, EditorGUIUtility.singleLineHeight);
            label = EditorGUI.BeginProperty(row, label, property);
            property.isExpanded = EditorGUI.Foldout(row, property.isExpanded, label, true);
            EditorGUI.EndProperty();
            if (!property.isExpanded) return;
            EditorGUI.indentLevel++;
            foreach (SettingField f in _fields)
            {
                row.y += Line;
                DrawField(row, property.FindPropertyRelative(f.name), f);
            }
            string problem = Problem(property);
            if (problem != null)
                EditorGUI.HelpBox(new Rect(row.x, row.y + Line, row.width, HelpBoxLines * Line - EditorGUIUtility.standardVerticalSpacing), problem, MessageType.Error);
            EditorGUI.indentLevel--;
        }

        string Problem(SerializedProperty property) => SettingFields.Problem(Selected(property));

        /// <summary>
        /// Each selected object's struct: a field of the object itself is read from each target (the
        /// property's boxedValue holds the first selected only); a struct nested deeper, the first selected's.
        /// </summary>
        (string, object)[] Selected(SerializedProperty property)
        {
            Object[] targets = property.serializedObject.targetObjects;
            if (property.propertyPath != fieldInfo.Name) return new (string, object)[] { (targets[0].name, property.boxedValue) };
            return targets.Select(t => (t.name, fieldInfo.GetValue(t))).ToArray();
        }

        /// <summary>One field's slider (the renderer inspector's too); mixed values and overrides as Unity shows them.</summary>
        internal static void DrawField(Rect rect, SerializedProperty p, SettingField f)
        {
            var label = new GUIContent(f.label, f.tooltip);
            if (!f.whole) EditorGUI.Slider(rect, p, f.min, f.max, label);
            else if (p.propertyType == SerializedPropertyType.Integer) EditorGUI.IntSlider(rect, p, (int)f.min, (int)f.max, label);
            else DrawWholeFloat(rect, p, f, label);
        }

        /// <summary>A whole number stored as a float (TessellationSettings.uniformFactor).</summary>
        static void DrawWholeFloat(Rect rect, SerializedProperty p, SettingField f, GUIContent label)
        {
            label = EditorGUI.BeginProperty(rect, label, p);
            EditorGUI.showMixedValue = p.hasMultipleDifferentValues;
            EditorGUI.BeginChangeCheck();
            int chosen = EditorGUI.IntSlider(rect, label, Mathf.RoundToInt(p.floatValue), (int)f.min, (int)f.max);
            if (EditorGUI.EndChangeCheck()) p.floatValue = chosen;
            EditorGUI.showMixedValue = false;
            EditorGUI.EndProperty();
        }
    }

    [CustomPropertyDrawer(typeof(TessellationSettings))]
    internal sealed class TessellationSettingsDrawer : SettingsDrawer
    {
        public TessellationSettingsDrawer() : base(SettingFields.Tessellation) { }
    }

    [CustomPropertyDrawer(typeof(NoiseSettings))]
    internal sealed class NoiseSettingsDrawer : SettingsDrawer
    {
        public NoiseSettingsDrawer() : base(SettingFields.Noise) { }
    }

    [CustomPropertyDrawer(typeof(HeightColorSettings))]
    internal sealed class HeightColorSettingsDrawer : SettingsDrawer
    {
        public HeightColorSettingsDrawer() : base(SettingFields.HeightColor) { }
    }
}
