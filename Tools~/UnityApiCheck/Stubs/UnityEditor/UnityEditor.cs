// A STUB of the UnityEditor members the package uses, written from Unity's Scripting Reference
// (2022.3; SR:<Page> = https://docs.unity3d.com/2022.3/Documentation/ScriptReference/<Page>.html).
// NOT Unity's assembly: signatures only.
#pragma warning disable CS0067, CS1591
using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    public static class AssemblyReloadEvents                                                 // SR:AssemblyReloadEvents
    {
        public delegate void AssemblyReloadCallback();                                       // SR:AssemblyReloadEvents.AssemblyReloadCallback (nested)
        public static event AssemblyReloadCallback beforeAssemblyReload;                     // SR:AssemblyReloadEvents-beforeAssemblyReload
    }

    // No AttributeUsage in 2022.3 (so: any target, not AllowMultiple, inherited); not sealed.
    public class CustomEditor : Attribute                                                    // SR:CustomEditor
    {
        public CustomEditor(Type inspectedType) { }                                          // SR:CustomEditor-ctor
        public CustomEditor(Type inspectedType, bool editorForChildClasses) { }              // SR:CustomEditor-ctor
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute                                                 // SR:MenuItem-ctor
    {
        public MenuItem(string itemName) { }                                              // SR:MenuItem-ctor
        public MenuItem(string itemName, bool isValidateFunction) { }                     // SR:MenuItem-ctor
        public MenuItem(string itemName, bool isValidateFunction, int priority) { }       // SR:MenuItem-ctor
    }


    public class Editor : UnityEngine.ScriptableObject                                       // SR:Editor
    {
        public Object target { get => null; set { } }                                       // SR:Editor-target
        public Object[] targets => null;                                                     // SR:Editor-targets (get only)
        public virtual void OnInspectorGUI() { }                                             // SR:Editor.OnInspectorGUI
        public virtual bool RequiresConstantRepaint() => false;                              // SR:Editor.RequiresConstantRepaint
        public bool DrawDefaultInspector() => false;                                         // SR:Editor.DrawDefaultInspector
        public SerializedObject serializedObject => null;                                    // SR:Editor-serializedObject (get only)
        public void Repaint() { }                                                            // SR:Editor.Repaint
    }

    // No AttributeUsage in 2022.3 (so: any target, not AllowMultiple, inherited).
    public sealed class CanEditMultipleObjects : Attribute { }                                // SR:CanEditMultipleObjects

    public partial class SerializedObject : IDisposable                                              // SR:SerializedObject
    {
        public SerializedProperty FindProperty(string propertyPath) => null;                 // SR:SerializedObject.FindProperty
        public bool UpdateIfRequiredOrScript() => false;                                     // SR:SerializedObject.UpdateIfRequiredOrScript
        public void Update() { }                                                             // SR:SerializedObject.Update
        public bool ApplyModifiedProperties() => false;                                      // SR:SerializedObject.ApplyModifiedProperties
        public bool isEditingMultipleObjects => false;                                       // SR:SerializedObject-isEditingMultipleObjects (get only)
        public void Dispose() { }                                                            // SR:SerializedObject.Dispose
    }

    public partial class SerializedProperty : IDisposable                                           // SR:SerializedProperty
    {
        public bool hasMultipleDifferentValues => false;                                     // SR:SerializedProperty-hasMultipleDifferentValues (get only)
        public SerializedProperty FindPropertyRelative(string relativePropertyPath) => null; // SR:SerializedProperty.FindPropertyRelative
        public bool isExpanded { get => false; set { } }                                     // SR:SerializedProperty-isExpanded
        public SerializedPropertyType propertyType => SerializedPropertyType.Integer;        // SR:SerializedProperty-propertyType (get only)
        public object boxedValue { get => null; set { } }                                    // SR:SerializedProperty-boxedValue (2022.1+)
        public int intValue { get => 0; set { } }                                            // SR:SerializedProperty-intValue
        public float floatValue { get => 0f; set { } }                                       // SR:SerializedProperty-floatValue
        public bool boolValue { get => false; set { } }                                      // SR:SerializedProperty-boolValue
        public Object objectReferenceValue { get => null; set { } }                          // SR:SerializedProperty-objectReferenceValue
        public int enumValueIndex { get => 0; set { } }                                      // SR:SerializedProperty-enumValueIndex
        public string tooltip => null;                                                       // SR:SerializedProperty-tooltip (get only)
        public void Dispose() { }                                                            // SR:SerializedProperty.Dispose
    }

    // SR:SerializedPropertyType (the members the package names; values as in SerializedProperty.bindings.cs)
    public enum SerializedPropertyType { Generic = -1, Integer = 0, Float = 2 }

    // Editor/Mono/ScriptAttributeGUI/GUIDrawer.cs, PropertyDrawer.cs, CustomPropertyDrawerAttribute.cs in 2022.3.
    public abstract class GUIDrawer { }                                                      // SR:GUIDrawer
    public abstract partial class PropertyDrawer : GUIDrawer                                       // SR:PropertyDrawer
    {
        public virtual void OnGUI(Rect position, SerializedProperty property, GUIContent label) { }          // SR:PropertyDrawer.OnGUI
        public virtual float GetPropertyHeight(SerializedProperty property, GUIContent label) => 18f;        // SR:PropertyDrawer.GetPropertyHeight
    }
    [AttributeUsage(AttributeTargets.Class, Inherited = false, AllowMultiple = true)]
    public sealed class CustomPropertyDrawer : Attribute                                     // SR:CustomPropertyDrawer
    {
        public CustomPropertyDrawer(Type type) { }                                           // SR:CustomPropertyDrawer-ctor
    }

    public sealed partial class EditorGUIUtility : GUIUtility                                // SR:EditorGUIUtility (sealed partial in 2022.3)
    {
        public static float singleLineHeight => 18f;                                         // SR:EditorGUIUtility-singleLineHeight (get only)
        public static float standardVerticalSpacing => 2f;                                   // SR:EditorGUIUtility-standardVerticalSpacing (get only)
    }

    public sealed class EditorPrefs                                                          // SR:EditorPrefs
    {
        public static bool GetBool(string key, bool defaultValue) => defaultValue;           // SR:EditorPrefs.GetBool
        public static void SetBool(string key, bool value) { }                               // SR:EditorPrefs.SetBool
    }

    public partial class EditorWindow : UnityEngine.ScriptableObject                         // SR:EditorWindow (partial in 2022.3)
    {
        public static T GetWindow<T>(string title) where T : EditorWindow => null;           // SR:EditorWindow.GetWindow
        public void Repaint() { }                                                            // SR:EditorWindow.Repaint
    }

    public enum MessageType { None = 0, Info = 1, Warning = 2, Error = 3 }                   // SR:MessageType

    public sealed class EditorGUI                                                            // SR:EditorGUI
    {
        public struct DisabledScope : IDisposable                                            // SR:EditorGUI.DisabledScope
        {
            public DisabledScope(bool disabled) { }                                       // SR:EditorGUI.DisabledScope-ctor
            public void Dispose() { }                                                     // SR:EditorGUI.DisabledScope.Dispose
        }
        public static void BeginChangeCheck() { }                                            // SR:EditorGUI.BeginChangeCheck
        public static bool EndChangeCheck() => false;                                        // SR:EditorGUI.EndChangeCheck
        public static bool showMixedValue { get => false; set { } }                          // SR:EditorGUI-showMixedValue
        public static GUIContent BeginProperty(Rect totalPosition, GUIContent label, SerializedProperty property) => label; // SR:EditorGUI.BeginProperty
        public static void EndProperty() { }                                                 // SR:EditorGUI.EndProperty
        public static float FloatField(Rect position, GUIContent label, float value) => value; // SR:EditorGUI.FloatField
        public static float DelayedFloatField(Rect position, GUIContent label, float value) => value; // SR:EditorGUI.DelayedFloatField
        public static float Slider(Rect position, GUIContent label, float value, float leftValue, float rightValue) => value; // SR:EditorGUI.Slider
        public static int Popup(Rect position, GUIContent label, int selectedIndex, GUIContent[] displayedOptions) => selectedIndex; // SR:EditorGUI.Popup
        public static void DrawPreviewTexture(Rect position, Texture image) { }              // SR:EditorGUI.DrawPreviewTexture
        public static int indentLevel { get => 0; set { } }                                  // SR:EditorGUI-indentLevel
        public static bool Foldout(Rect position, bool foldout, GUIContent content, bool toggleOnLabelClick) => foldout; // SR:EditorGUI.Foldout
        public static void Slider(Rect position, SerializedProperty property, float leftValue, float rightValue, GUIContent label) { } // SR:EditorGUI.Slider
        public static void IntSlider(Rect position, SerializedProperty property, int leftValue, int rightValue, GUIContent label) { }   // SR:EditorGUI.IntSlider
        public static int IntSlider(Rect position, GUIContent label, int value, int leftValue, int rightValue) => value; // SR:EditorGUI.IntSlider
        public static void HelpBox(Rect position, string message, MessageType type) { }      // SR:EditorGUI.HelpBox
    }

    public sealed partial class EditorGUILayout                                              // SR:EditorGUILayout (sealed partial in 2022.3)
    {
        public static void LabelField(string label, string label2, params GUILayoutOption[] options) { }           // SR:EditorGUILayout.LabelField
        public static void LabelField(GUIContent label, GUIContent label2, params GUILayoutOption[] options) { }   // SR:EditorGUILayout.LabelField
        public static void HelpBox(string message, MessageType type) { }                                          // SR:EditorGUILayout.HelpBox
        public static void Space() { }                                                                              // SR:EditorGUILayout.Space
        public static int IntField(string label, int value, params GUILayoutOption[] options) => value;             // SR:EditorGUILayout.IntField
        public static int IntField(GUIContent label, int value, params GUILayoutOption[] options) => value;         // SR:EditorGUILayout.IntField
        public static float FloatField(GUIContent label, float value, params GUILayoutOption[] options) => value;   // SR:EditorGUILayout.FloatField
        public static Object ObjectField(GUIContent label, Object obj, Type objType, bool allowSceneObjects, params GUILayoutOption[] options) => obj; // SR:EditorGUILayout.ObjectField
        public static Enum EnumPopup(GUIContent label, Enum selected, params GUILayoutOption[] options) => selected; // SR:EditorGUILayout.EnumPopup
        public static bool Toggle(GUIContent label, bool value, params GUILayoutOption[] options) => value;        // SR:EditorGUILayout.Toggle
        public static bool PropertyField(SerializedProperty property, params GUILayoutOption[] options) => false;  // SR:EditorGUILayout.PropertyField
        public static bool BeginFoldoutHeaderGroup(bool foldout, string content, GUIStyle style = null, Action<Rect> menuAction = null, GUIStyle menuIcon = null) => foldout; // SR:EditorGUILayout.BeginFoldoutHeaderGroup
        public static void EndFoldoutHeaderGroup() { }                                                              // SR:EditorGUILayout.EndFoldoutHeaderGroup
    }

    public class EditorUtility                                                               // SR:EditorUtility (plain class in 2022.3)
    {
        public static string SaveFilePanel(string title, string directory, string defaultName, string extension) => null; // SR:EditorUtility.SaveFilePanel
        public static string OpenFilePanel(string title, string directory, string extension) => null;                     // SR:EditorUtility.OpenFilePanel
        public static void SetDirty(Object target) { }                                                                    // SR:EditorUtility.SetDirty
        public static bool DisplayDialog(string title, string message, string ok) => true;                                // SR:EditorUtility.DisplayDialog
        public static bool DisplayDialog(string title, string message, string ok, string cancel) => true;                 // SR:EditorUtility.DisplayDialog
        public static bool DisplayCancelableProgressBar(string title, string info, float progress) => false;              // SR:EditorUtility.DisplayCancelableProgressBar
        public static void ClearProgressBar() { }                                                                         // SR:EditorUtility.ClearProgressBar
        public static bool IsPersistent(Object target) => false;                                                          // SR:EditorUtility.IsPersistent
    }

    public partial class Undo                                                                // SR:Undo (plain partial class in 2022.3)
    {
        public static void RecordObject(Object objectToUndo, string name) { }                // SR:Undo.RecordObject
        public static void RegisterCreatedObjectUndo(Object objectToUndo, string name) { }   // SR:Undo.RegisterCreatedObjectUndo
        public static void PerformUndo() { }                                                 // SR:Undo.PerformUndo
    }

    public sealed partial class AssetDatabase                                                   // SR:AssetDatabase
    {
        public static void CreateAsset(Object asset, string path) { }                        // SR:AssetDatabase.CreateAsset
        public static string GenerateUniqueAssetPath(string path) => path;                   // SR:AssetDatabase.GenerateUniqueAssetPath
        public static void SaveAssetIfDirty(Object obj) { }                                  // SR:AssetDatabase.SaveAssetIfDirty
        public static bool DeleteAsset(string path) => false;                                // SR:AssetDatabase.DeleteAsset
    }

    public sealed partial class Selection { public static Object activeObject { get; set; } } // SR:Selection-activeObject

    public class SearchableEditorWindow : EditorWindow { }                                   // SR:SearchableEditorWindow
    public class SceneView : SearchableEditorWindow                                          // SR:SceneView
    {
        public static void RepaintAll() { }                                                  // SR:SceneView.RepaintAll
        public static SceneView lastActiveSceneView => null;                                 // SR:SceneView-lastActiveSceneView
        public Camera camera => null;                                                        // SR:SceneView-camera
    }

    public sealed class EditorApplication                                                    // SR:EditorApplication
    {
        public static double timeSinceStartup => 0.0;                                        // SR:EditorApplication-timeSinceStartup
        public static bool isPlayingOrWillChangePlaymode => false;                           // SR:EditorApplication-isPlayingOrWillChangePlaymode (get only)
        public static event Action hierarchyChanged;                                         // SR:EditorApplication-hierarchyChanged
        public delegate void CallbackFunction();                                             // SR:EditorApplication.CallbackFunction
        public static CallbackFunction update;                                               // SR:EditorApplication-update (a field, not an event)
    }

    public sealed partial class Handles                                                      // SR:Handles (sealed partial in 2022.3)
    {
        public delegate void CapFunction(int controlID, Vector3 position, Quaternion rotation, float size, EventType eventType); // SR:Handles.CapFunction
        public static Color color { get; set; }                                              // SR:Handles-color
        public static Matrix4x4 matrix { get; set; }                                         // SR:Handles-matrix
        public static void DrawLine(Vector3 p1, Vector3 p2) { }                              // SR:Handles.DrawLine
        public static bool Button(Vector3 position, Quaternion direction, float size, float pickSize, CapFunction capFunction) => false; // SR:Handles.Button
        public static void DotHandleCap(int controlID, Vector3 position, Quaternion rotation, float size, EventType eventType) { }     // SR:Handles.DotHandleCap
        public static Vector3 PositionHandle(Vector3 position, Quaternion rotation) => position;                                        // SR:Handles.PositionHandle
    }

    public sealed partial class HandleUtility                                                // SR:HandleUtility (sealed partial in 2022.3)
    {
        public static float GetHandleSize(Vector3 position) => 1f;                           // SR:HandleUtility.GetHandleSize
        public delegate GameObject PickGameObjectCallback(Camera cam, int layers, Vector2 position, GameObject[] ignore, GameObject[] filter, out int materialIndex); // SR:HandleUtility.PickGameObjectCallback (nested)
        public static event PickGameObjectCallback pickGameObjectCustomPasses;               // SR:HandleUtility-pickGameObjectCustomPasses
    }
}
