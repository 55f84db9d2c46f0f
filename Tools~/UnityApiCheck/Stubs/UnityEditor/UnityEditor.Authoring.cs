// STUB members of UnityEditor used by the sculpt tool and the region refit (issue 27, deliverable 3),
// kept apart from UnityEditor.cs so that changes there merge cleanly. Checked against UnityCsReference
// 2022.3: Editor/Mono/GUI/Tools/EditorTool.cs, EditorToolAttributes.cs, ToolManager.cs,
// Editor/Mono/HandleUtility.cs, Editor/Mono/Handles.cs, Editor/Mono/Undo/Undo.bindings.cs,
// Editor/Mono/EditorGUILayout.cs. SR:<Page> as in UnityEditor.cs. NOT Unity's assembly: signatures only.
#pragma warning disable CS1591
using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor.EditorTools
{
    public abstract class ToolAttribute : Attribute                                          // SR:EditorTools.ToolAttribute
    {
        ToolAttribute() { }
        protected ToolAttribute(string displayName, Type targetType = null, Type editorToolContext = null) { } // SR:EditorTools.ToolAttribute-ctor
        public string displayName => null;                                                   // SR:EditorTools.ToolAttribute-displayName
        public Type targetType => null;                                                      // SR:EditorTools.ToolAttribute-targetType
        public Type targetContext => null;                                                   // SR:EditorTools.ToolAttribute-targetContext
    }

    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class EditorToolAttribute : ToolAttribute                                  // SR:EditorTools.EditorToolAttribute
    {
        public EditorToolAttribute(string displayName, Type componentToolTarget = null) : base(displayName, componentToolTarget) { }  // SR:EditorTools.EditorToolAttribute-ctor
        public EditorToolAttribute(string displayName, Type componentToolTarget, Type editorToolContext) : base(displayName, componentToolTarget, editorToolContext) { } // SR:EditorTools.EditorToolAttribute-ctor
    }

    public abstract class EditorTool : ScriptableObject                                      // SR:EditorTools.EditorTool
    {
        public IEnumerable<Object> targets => null;                                          // SR:EditorTools.EditorTool-targets
        public Object target => null;                                                        // SR:EditorTools.EditorTool-target
        public virtual GUIContent toolbarIcon => null;                                       // SR:EditorTools.EditorTool-toolbarIcon
        public virtual bool gridSnapEnabled => false;                                        // SR:EditorTools.EditorTool-gridSnapEnabled
        public virtual void OnActivated() { }                                                // SR:EditorTools.EditorTool.OnActivated
        public virtual void OnWillBeDeactivated() { }                                        // SR:EditorTools.EditorTool.OnWillBeDeactivated
        public virtual void OnToolGUI(EditorWindow window) { }                               // SR:EditorTools.EditorTool.OnToolGUI
        public virtual bool IsAvailable() => true;                                           // SR:EditorTools.EditorTool.IsAvailable
    }

    public static class ToolManager                                                          // SR:EditorTools.ToolManager
    {
        public static Type activeToolType => null;                                           // SR:EditorTools.ToolManager-activeToolType
        public static void SetActiveTool<T>() where T : EditorTool { }                       // SR:EditorTools.ToolManager.SetActiveTool
        public static void RestorePreviousPersistentTool() { }                               // SR:EditorTools.ToolManager.RestorePreviousPersistentTool
    }
}

namespace UnityEditor
{
    public sealed partial class HandleUtility
    {
        public static Ray GUIPointToWorldRay(Vector2 position) => default;                   // SR:HandleUtility.GUIPointToWorldRay
        public static void AddDefaultControl(int controlId) { }                              // SR:HandleUtility.AddDefaultControl
        public static void Repaint() { }                                                     // SR:HandleUtility.Repaint
    }

    public sealed partial class Handles
    {
        public static void DrawWireDisc(Vector3 center, Vector3 normal, float radius) { }   // SR:Handles.DrawWireDisc
        public static void Label(Vector3 position, string text) { }                         // SR:Handles.Label
    }

    public partial class Undo
    {
        public static void IncrementCurrentGroup() { }                                       // SR:Undo.IncrementCurrentGroup
        public static int GetCurrentGroup() => 0;                                            // SR:Undo.GetCurrentGroup
        public static void SetCurrentGroupName(string name) { }                              // SR:Undo.SetCurrentGroupName
        public static void CollapseUndoOperations(int groupIndex) { }                        // SR:Undo.CollapseUndoOperations
        public static T AddComponent<T>(GameObject gameObject) where T : Component => null;  // SR:Undo.AddComponent
    }

    public sealed partial class EditorGUILayout
    {
        public static float Slider(GUIContent label, float value, float leftValue, float rightValue, params GUILayoutOption[] options) => value; // SR:EditorGUILayout.Slider
        public static Rect GetControlRect(params GUILayoutOption[] options) => default;     // SR:EditorGUILayout.GetControlRect
        public static int Popup(GUIContent label, int selectedIndex, GUIContent[] displayedOptions, params GUILayoutOption[] options) => selectedIndex; // SR:EditorGUILayout.Popup
    }
}
