using System;
using System.Threading;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// GameObject > Gregory Terrain > Convert Selected Terrain: a new Gregory terrain with the selected
    /// Unity Terrain's size, position and heights (fitted by least squares); the Terrain is only read.
    /// </summary>
    internal static class TerrainConversion
    {
        const string MenuPath = "GameObject/Gregory Terrain/Convert Selected Terrain";
        /// <summary>RMS target as a fraction of the terrain's height range, and the most patches a side tried.</summary>
        const double RmsTargetOfHeight = 1e-3;
        const int MaxColumns = 256;

        [MenuItem(MenuPath, true, 11)]
        static bool CanConvert() => Selected() != null;

        [MenuItem(MenuPath, false, 11)]
        static void Convert()
        {
            Terrain terrain = Selected();
            if (terrain == null) return;
            TerrainData data = terrain.terrainData;
            if (data == null)
            {
                EditorUtility.DisplayDialog("Convert terrain", $"'{terrain.name}' has no TerrainData: nothing to convert.", "OK");
                return;
            }
            Vector3 size = data.size;
            int res = data.heightmapResolution;
            using var cancel = new CancellationTokenSource();
            try
            {
                double[] z = TerrainHeights.FromUnity(data.GetHeights(0, 0, res, res), size.x, size.y, size.z);
                var progress = new CancelableProgressBar($"Converting '{terrain.name}' ({res} x {res} heights)", cancel);
                HeightmapFit fit = HeightmapFitter.FitToTarget(z, res, res, RmsTargetOfHeight * size.y / size.x, FitErrorKind.Rms, MaxColumns, progress, cancel.Token);

                var grid = ScriptableObject.CreateInstance<PatchGridAsset>();
                grid.SetGrid(fit.Grid, PatchGridBlocks.FromGrid(fit.Grid), out PatchGridBlock[] blocks, out _);
                AssetDatabase.CreateAsset(grid, AssetDatabase.GenerateUniqueAssetPath($"Assets/{terrain.name} Patch Grid.asset"));
                // The control points live in block objects: sub-assets of the grid's file, or the saved
                // grid refers to objects that are gone after a reload ("blocks[0] is missing").
                foreach (PatchGridBlock b in blocks) AssetDatabase.AddObjectToAsset(b, grid);
                var go = new GameObject($"{terrain.name} (Gregory)");
                go.transform.position = terrain.transform.position;
                go.transform.localScale = new Vector3(size.x, size.x, size.z);
                var renderer = go.AddComponent<GregoryTerrainRenderer>();
                Shader shader = Shader.Find(GregoryTerrainMenu.ShaderName);
                if (shader != null)
                {
                    var material = new Material(shader);
                    AssetDatabase.CreateAsset(material, AssetDatabase.GenerateUniqueAssetPath("Assets/Gregory Terrain.mat"));
                    renderer.Material = material;
                }
                else Debug.LogWarning($"Shader '{GregoryTerrainMenu.ShaderName}' not found; assign a material by hand.", go);
                renderer.Grid = grid;
                Undo.RegisterCreatedObjectUndo(go, "Convert Terrain to Gregory Terrain");
                Selection.activeObject = go;
                Debug.Log($"Converted '{terrain.name}' to {fit.Grid.Columns} x {fit.Grid.Rows} Gregory patches: height error max {fit.MaxError * size.x:G3} m, RMS {fit.RmsError * size.x:G3} m against its {res} x {res} heights.", go);
            }
            catch (OperationCanceledException) { Debug.Log($"Converting '{terrain.name}' was cancelled; nothing was created.", terrain); }
            catch (ArgumentException e) { EditorUtility.DisplayDialog("Convert terrain", $"'{terrain.name}': {e.Message}", "OK"); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        static Terrain Selected() => Selection.activeObject is GameObject g ? g.GetComponent<Terrain>() : null;
    }
}
