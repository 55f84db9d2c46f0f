using System.Collections.Generic;
using System.Linq;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Renames prefab overrides of the renderer's old flat settings to the struct paths
    /// (OverridePathUpgrade): for the instances in a scene when it opens, in a prefab when Prefab Mode
    /// opens it (both as undoable edits, saved with the scene or prefab), and in every scene and prefab
    /// of the project from the menu.
    /// </summary>
    [InitializeOnLoad]
    internal static class FlatSettingsOverrideUpgrader
    {
        const string Title = "Upgrade Gregory Terrain overrides";

        static bool _projectPass;   // the menu opens scenes itself, saves them, and records no undo for files it closes

        static FlatSettingsOverrideUpgrader()
        {
            EditorSceneManager.sceneOpened += (scene, mode) => { if (!_projectPass) UpgradeAll(scene.GetRootGameObjects(), true); };
            PrefabStage.prefabStageOpened += stage => UpgradeAll(new[] { stage.prefabContentsRoot }, true);
        }

        /// <summary>Each prefab instance under <paramref name="roots"/> holding a renderer, once; true when any changed.</summary>
        static bool UpgradeAll(IEnumerable<GameObject> roots, bool undoable)
        {
            bool changed = false;
            foreach (GameObject instance in roots.SelectMany(r => r.GetComponentsInChildren<GregoryTerrainRenderer>(true))
                         .Where(PrefabUtility.IsPartOfPrefabInstance).Select(PrefabUtility.GetOutermostPrefabInstanceRoot).Distinct())
                changed |= Upgrade(instance, undoable);
            return changed;
        }

        static bool Upgrade(GameObject instance, bool undoable)
        {
            PropertyModification[] mods = PrefabUtility.GetPropertyModifications(instance);
            if (mods == null) return false;
            List<PropertyModification> now = OverridePathUpgrade.Rewrite(mods, m => m.target as GregoryTerrainRenderer, m => m.propertyPath,
                (m, path) => new PropertyModification { target = m.target, propertyPath = path, value = m.value, objectReference = m.objectReference });
            if (now == null) return false;
            if (undoable) Undo.RegisterCompleteObjectUndo(PrefabUtility.GetPrefabInstanceHandle(instance), Title);
            PrefabUtility.SetPropertyModifications(instance, now.ToArray());
            return true;
        }

        [MenuItem("Tools/Gregory Terrain/" + Title)]
        static void UpgradeProject()
        {
            if (!EditorUtility.DisplayDialog(Title, "Rename the old Gregory Terrain settings overrides (tiles, noiseAmplitude, ...) in every scene and prefab under Assets, "
                    + "and save the files changed. This cannot be undone: commit or back up the project first.", "Upgrade", "Cancel")) return;
            if (!EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo()) return;
            string[] paths = AssetDatabase.FindAssets("t:Prefab t:Scene").Select(AssetDatabase.GUIDToAssetPath)
                .Where(p => p.StartsWith("Assets/")).Distinct().ToArray();
            int upgraded = 0, done = 0;
            _projectPass = true;
            try
            {
                for (; done < paths.Length; done++)
                {
                    if (EditorUtility.DisplayCancelableProgressBar(Title, paths[done], (float)done / paths.Length)) break;
                    if (paths[done].EndsWith(".unity") ? UpgradeSceneFile(paths[done]) : UpgradePrefabFile(paths[done])) upgraded++;
                }
            }
            finally { _projectPass = false; EditorUtility.ClearProgressBar(); }
            string stopped = done < paths.Length ? $" Cancelled after {done} of {paths.Length}; the rest are unchanged." : "";
            EditorUtility.DisplayDialog(Title, $"Rewrote the overrides in {upgraded} scene(s) and prefab(s) and saved them.{stopped}", "OK");
        }

        /// <summary>An open scene is upgraded in place and saved; another is opened beside it and closed again.</summary>
        static bool UpgradeSceneFile(string path)
        {
            Scene scene = SceneManager.GetSceneByPath(path);
            bool wasOpen = scene.IsValid() && scene.isLoaded;
            if (!wasOpen) scene = EditorSceneManager.OpenScene(path, OpenSceneMode.Additive);
            bool changed = UpgradeAll(scene.GetRootGameObjects(), wasOpen);
            if (changed) EditorSceneManager.SaveScene(scene);
            if (!wasOpen) EditorSceneManager.CloseScene(scene, true);
            return changed;
        }

        static bool UpgradePrefabFile(string path)
        {
            GameObject root = PrefabUtility.LoadPrefabContents(path);
            try
            {
                bool changed = UpgradeAll(new[] { root }, false);
                if (changed) PrefabUtility.SaveAsPrefabAsset(root, path);
                return changed;
            }
            finally { PrefabUtility.UnloadPrefabContents(root); }
        }
    }
}
