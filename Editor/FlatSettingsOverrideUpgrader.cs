using System;
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
    /// (OverridePathUpgrade) in every scene and prefab under Assets/, from the menu: an explicit pass,
    /// so that opening a scene never modifies it (read-only or locked files, Auto Save in Prefab Mode).
    /// </summary>
    internal static class FlatSettingsOverrideUpgrader
    {
        const string Title = "Upgrade Gregory Terrain overrides";
        const string MenuPath = "Tools/Gregory Terrain/" + Title;

        /// <summary>
        /// Each prefab instance under <paramref name="roots"/> holding a renderer, once; true when any has
        /// old overrides (renamed unless <paramref name="apply"/> is false: a dry run).
        /// </summary>
        static bool UpgradeAll(IEnumerable<GameObject> roots, bool apply = true)
        {
            bool changed = false;
            foreach (GameObject instance in roots.SelectMany(r => r.GetComponentsInChildren<GregoryTerrainRenderer>(true))
                         .Where(PrefabUtility.IsPartOfPrefabInstance).Select(PrefabUtility.GetOutermostPrefabInstanceRoot).Distinct())
                changed |= Upgrade(instance, apply);
            return changed;
        }

        static bool Upgrade(GameObject instance, bool apply)
        {
            PropertyModification[] mods = PrefabUtility.GetPropertyModifications(instance);
            if (mods == null) return false;
            List<PropertyModification> now = OverridePathUpgrade.Rewrite(mods, m => m.target as GregoryTerrainRenderer, m => m.propertyPath,
                (m, path) => new PropertyModification { target = m.target, propertyPath = path, value = m.value, objectReference = m.objectReference });
            if (now == null) return false;
            if (apply) PrefabUtility.SetPropertyModifications(instance, now.ToArray());
            return true;
        }

        [MenuItem(MenuPath, true)]
        static bool CanUpgradeProject() => !EditorApplication.isPlayingOrWillChangePlaymode;

        [MenuItem(MenuPath)]
        static void UpgradeProject()
        {
            if (PrefabStageUtility.GetCurrentPrefabStage() != null)
            {
                EditorUtility.DisplayDialog(Title, "Close Prefab Mode first: the pass rewrites prefab files, and the open prefab's unsaved edits would be lost.", "OK");
                return;
            }
            if (!EditorUtility.DisplayDialog(Title, "Rename the old Gregory Terrain settings overrides (tiles, noiseAmplitude, ...) in every scene and prefab under Assets, "
                    + "and save the files changed. This cannot be undone: commit or back up the project first.", "Upgrade", "Cancel")) return;
            if (!EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo()) return;
            string[] paths = AssetDatabase.FindAssets("t:Prefab t:Scene").Select(AssetDatabase.GUIDToAssetPath)
                .Where(p => p.StartsWith("Assets/") && (p.EndsWith(".prefab") || p.EndsWith(".unity"))).Distinct().ToArray();
            var upgraded = new List<string>();
            var failed = new List<string>();
            int done = 0;
            try
            {
                for (; done < paths.Length; done++)
                {
                    if (EditorUtility.DisplayCancelableProgressBar(Title, paths[done], (float)done / paths.Length)) break;
                    try
                    {
                        string problem = paths[done].EndsWith(".unity") ? UpgradeSceneFile(paths[done], out bool changed) : UpgradePrefabFile(paths[done], out changed);
                        if (problem != null) failed.Add($"{paths[done]}: {problem}");
                        else if (changed) upgraded.Add(paths[done]);
                    }
                    catch (Exception e)
                    {
                        failed.Add($"{paths[done]}: {e.Message}");
                        Debug.LogException(e);
                    }
                }
            }
            finally { EditorUtility.ClearProgressBar(); }
            EditorUtility.DisplayDialog(Title, Summary(upgraded.Count, failed, done, paths.Length), "OK");
        }

        static string Summary(int upgraded, List<string> failed, int done, int total)
        {
            string text = $"Rewrote and saved the overrides in {upgraded} scene(s) and prefab(s).";
            if (done < total) text += $" Cancelled after {done} of {total}; the rest are unchanged.";
            if (failed.Count > 0) text += $"\n\nNot upgraded ({failed.Count}):\n" + string.Join("\n", failed.Take(10)) + (failed.Count > 10 ? "\n..." : "");
            return text;
        }

        /// <summary>
        /// A loaded scene is upgraded in place and saved; a scene not loaded is opened beside the others and
        /// closed again, kept in the Hierarchy if it was there (unloaded). Null, or why the file was left.
        /// </summary>
        static string UpgradeSceneFile(string path, out bool changed)
        {
            changed = false;
            Scene scene = SceneManager.GetSceneByPath(path);
            bool wasLoaded = scene.IsValid() && scene.isLoaded, wasListed = scene.IsValid();
            if (wasLoaded && scene.isDirty)
                return UpgradeAll(scene.GetRootGameObjects(), apply: false) ? "has unsaved changes (not saved when asked)" : null;
            if (!wasLoaded) scene = EditorSceneManager.OpenScene(path, OpenSceneMode.Additive);
            try
            {
                changed = UpgradeAll(scene.GetRootGameObjects());
                if (!changed || EditorSceneManager.SaveScene(scene)) return null;
                return wasLoaded ? "renamed in the open scene, not saved (read-only or locked?)" : "could not be saved (read-only or locked?)";
            }
            finally
            {
                if (!wasLoaded) EditorSceneManager.CloseScene(scene, !wasListed);
            }
        }

        static string UpgradePrefabFile(string path, out bool changed)
        {
            GameObject root = PrefabUtility.LoadPrefabContents(path);
            try
            {
                changed = UpgradeAll(new[] { root });
                if (!changed) return null;
                PrefabUtility.SaveAsPrefabAsset(root, path, out bool saved);
                return saved ? null : "could not be saved (read-only or locked?)";
            }
            finally { PrefabUtility.UnloadPrefabContents(root); }
        }
    }
}
