// STUB members for the upgrade of old prefab overrides (FlatSettingsOverrideUpgrader) and the settings
// drawers' per-object check, in a file of their own so other stub edits merge cleanly. From the 2022.3
// Scripting Reference (SR:<Page>), checked against UnityCsReference 2022.3:
// Editor/Mono/Prefabs/PrefabUtility.bindings.cs (:45, :95, :99, :372, :411), PrefabUtility.cs (:2093,
// :2871, :2895), Prefabs/PropertyModification.bindings.cs, EditorSceneManager.cs (:14, :16, :44, :60, :86),
// EditorSceneManager.bindings.cs (:79, :125), SceneManagement/StageManager/Stage.cs,
// PreviewSceneStage.cs, PrefabStage/PrefabStage.cs (:58, :271), Undo/Undo.bindings.cs:100,
// AssetDatabase/AssetDatabaseSearching.cs:16, ScriptAttributeGUI/PropertyDrawer.cs:23,
// SerializedObject.bindings.cs:157, SerializedProperty.bindings.cs.
#pragma warning disable CS0067, CS1591
using System;
using System.Reflection;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    [Serializable]
    public sealed class PropertyModification                                                 // SR:PropertyModification
    {
        public Object target;                                                                // SR:PropertyModification-target
        public string propertyPath;                                                          // SR:PropertyModification-propertyPath
        public string value;                                                                 // SR:PropertyModification-value
        public Object objectReference;                                                       // SR:PropertyModification-objectReference
    }

    public sealed partial class PrefabUtility                                                // SR:PrefabUtility
    {
        public static PropertyModification[] GetPropertyModifications(Object targetPrefab) => null;                 // SR:PrefabUtility.GetPropertyModifications
        public static void SetPropertyModifications(Object targetPrefab, PropertyModification[] modifications) { }  // SR:PrefabUtility.SetPropertyModifications
        public static Object GetPrefabInstanceHandle(Object instanceComponentOrGameObject) => null;                 // SR:PrefabUtility.GetPrefabInstanceHandle
        public static bool IsPartOfPrefabInstance(Object componentOrGameObject) => false;                          // SR:PrefabUtility.IsPartOfPrefabInstance
        public static GameObject GetOutermostPrefabInstanceRoot(Object componentOrGameObject) => null;             // SR:PrefabUtility.GetOutermostPrefabInstanceRoot
        public static GameObject LoadPrefabContents(string assetPath) => null;                                     // SR:PrefabUtility.LoadPrefabContents
        public static void UnloadPrefabContents(GameObject contentsRoot) { }                                       // SR:PrefabUtility.UnloadPrefabContents
        public static GameObject SaveAsPrefabAsset(GameObject instanceRoot, string assetPath) => null;             // SR:PrefabUtility.SaveAsPrefabAsset
        public static GameObject SaveAsPrefabAsset(GameObject instanceRoot, string assetPath, out bool success) { success = false; return null; } // SR:PrefabUtility.SaveAsPrefabAsset
    }

    public partial class Undo
    {
        public static void RegisterCompleteObjectUndo(Object objectToUndo, string name) { }  // SR:Undo.RegisterCompleteObjectUndo
    }

    public sealed partial class AssetDatabase
    {
        public static string[] FindAssets(string filter) => null;                            // SR:AssetDatabase.FindAssets
    }

    public abstract partial class PropertyDrawer
    {
        public FieldInfo fieldInfo => null;                                                  // SR:PropertyDrawer-fieldInfo (get only)
    }

    public partial class SerializedObject
    {
        public Object[] targetObjects => null;                                               // SR:SerializedObject-targetObjects (get only)
    }

    public partial class SerializedProperty
    {
        public SerializedObject serializedObject => null;                                    // SR:SerializedProperty-serializedObject (get only)
        public string propertyPath => null;                                                  // SR:SerializedProperty-propertyPath (get only)
    }
}

namespace UnityEditor.SceneManagement
{
    public enum OpenSceneMode { Single, Additive, AdditiveWithoutLoading }                   // SR:SceneManagement.OpenSceneMode

    public sealed partial class EditorSceneManager
    {
        public delegate void SceneOpenedCallback(Scene scene, OpenSceneMode mode);          // SR:SceneManagement.EditorSceneManager.SceneOpenedCallback
        public static event SceneOpenedCallback sceneOpened;                                 // SR:SceneManagement.EditorSceneManager-sceneOpened
        public static Scene OpenScene(string scenePath, OpenSceneMode mode) => default;      // SR:SceneManagement.EditorSceneManager.OpenScene
        public static bool SaveScene(Scene scene) => false;                                  // SR:SceneManagement.EditorSceneManager.SaveScene
        public static bool CloseScene(Scene scene, bool removeScene) => false;               // SR:SceneManagement.EditorSceneManager.CloseScene
        public static bool SaveCurrentModifiedScenesIfUserWantsTo() => false;                // SR:SceneManagement.EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo
    }

    public abstract class Stage : ScriptableObject { }                                       // SR:SceneManagement.Stage
    public abstract class PreviewSceneStage : Stage { }                                      // SR:SceneManagement.PreviewSceneStage

    public sealed partial class PrefabStage : PreviewSceneStage                              // SR:SceneManagement.PrefabStage
    {
        public static event Action<PrefabStage> prefabStageOpened;                           // SR:SceneManagement.PrefabStage-prefabStageOpened
        public GameObject prefabContentsRoot => null;                                        // SR:SceneManagement.PrefabStage-prefabContentsRoot (get only)
    }

    public static class PrefabStageUtility                                                   // SR:SceneManagement.PrefabStageUtility (PrefabStageUtility.cs:20)
    {
        public static PrefabStage GetCurrentPrefabStage() => null;                           // SR:SceneManagement.PrefabStageUtility.GetCurrentPrefabStage (:252)
    }
}
