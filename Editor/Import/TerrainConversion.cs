using System;
using System.Collections.Generic;
using System.Threading;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// GameObject &gt; Gregory Terrain &gt; Convert Selected Terrain: one Gregory terrain, in metres, from
    /// the selected Unity Terrain or group of adjacent, equal Terrain tiles (Core's TileGroupAuthoring:
    /// one seamless grid). The whole fit runs first, with a progress bar and Cancel; only then are the
    /// assets and the GameObject made and the source Terrains deactivated, all one undo step, so a
    /// cancel or a refusal changes nothing.
    /// </summary>
    internal static class TerrainConversion
    {
        const string MenuPath = "GameObject/Gregory Terrain/Convert Selected Terrain";
        const string UndoName = "Convert Terrain to Gregory Terrain";
        /// <summary>RMS target as a fraction of the terrain's height, and the most patches a side tried per tile.</summary>
        const double RmsTargetOfHeight = 1e-3;
        const int MaxColumns = 256;

        [MenuItem(MenuPath, true, 11)]
        static bool CanConvert() => SelectedTerrains().Count > 0;

        [MenuItem(MenuPath, false, 11)]
        static void Convert()
        {
            List<Terrain> terrains = SelectedTerrains();
            if (terrains.Count == 0) return;
            var tiles = new List<TerrainTile>();
            foreach (Terrain t in terrains)
            {
                if (t.terrainData == null) { Refuse($"'{t.name}' has no TerrainData: nothing to convert."); return; }
                tiles.Add(Tile(t));
            }
            TerrainTile[,] group;
            try { group = TileGroupAuthoring.Arrange(tiles); }
            catch (ArgumentException e) { Refuse(e.Message + " Nothing was converted."); return; }

            TerrainTile first = group[0, 0];
            int n = group.GetLength(0), m = group.GetLength(1), res = first.Resolution;
            string what = n * m == 1 ? $"'{first.Name}'" : $"{n} x {m} tiles from '{first.Name}'";
            using var cancel = new CancellationTokenSource();
            var progress = new CancelableProgressBar($"Converting {what} ({res} x {res} heights a tile)", cancel);
            try
            {
                // Heights are fractions of the Terrain's height: with Height Scale = size.y they are metres.
                HeightmapFit sw = HeightmapFitter.FitToTarget(first.Heights, res, res, RmsTargetOfHeight, FitErrorKind.Rms, Math.Max(1, MaxColumns / n), progress, cancel.Token);
                PatchGrid grid = sw.Grid;
                double max = sw.MaxError, rms = sw.RmsError;
                if (n * m > 1) grid = TileGroupAuthoring.FitAndJoin(group, sw.Grid.Columns, sw.Grid.Rows, out max, out rms, progress, cancel.Token);
                GameObject go = Create(first, n, m, grid);
                Deactivate(terrains);
                Undo.SetCurrentGroupName(UndoName);
                Debug.Log($"Converted {what} to {grid.Columns} x {grid.Rows} Gregory patches: height error max {max * first.SizeY:G3} m, RMS {rms * first.SizeY:G3} m against the Terrain heights. The source Terrain GameObjects were deactivated (Undo brings them back).", go);
            }
            catch (OperationCanceledException) { Debug.Log($"Converting {what} was cancelled; nothing was changed.", terrains[0]); }
            catch (ArgumentException e) { Refuse($"{what}: {e.Message} Nothing was converted."); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        /// <summary>The new terrain over the whole group, at the south-west tile's corner, in metres (Transform scale 1).</summary>
        static GameObject Create(TerrainTile southWest, int columns, int rows, PatchGrid grid)
        {
            var go = new GameObject($"{southWest.Name} (Gregory)");
            PatchGridAsset asset = null;
            Material material = null;
            try
            {
                go.transform.position = new Vector3((float)southWest.X, (float)southWest.Y, (float)southWest.Z);
                var renderer = go.AddComponent<GregoryTerrainRenderer>();
                renderer.TerrainSize = new Vector2((float)(columns * southWest.SizeX), (float)(rows * southWest.SizeZ));   // refuses a bad size before any asset exists
                renderer.HeightScale = (float)southWest.SizeY;
                renderer.HorizonLevels = true;
                asset = TerrainAssets.CreateGrid(grid, $"Assets/{AssetFileName(southWest.Name)} Patch Grid.asset");
                renderer.Grid = asset;
                material = TerrainAssets.CreateMaterial(go, noise: false);   // the user's terrain as it was, no detail added
                renderer.Material = material;
                TerrainAssets.AssignComputeShaders(renderer);
            }
            catch
            {
                UnityEngine.Object.DestroyImmediate(go);
                if (asset != null) AssetDatabase.DeleteAsset(AssetDatabase.GetAssetPath(asset));
                if (material != null) AssetDatabase.DeleteAsset(AssetDatabase.GetAssetPath(material));
                throw;
            }
            Undo.RegisterCreatedObjectUndo(go, UndoName);
            Selection.activeObject = go;
            return go;
        }

        /// <summary>Deactivates the source Terrains' GameObjects, recorded for Undo: the converted terrain replaces them in the scene.</summary>
        static void Deactivate(List<Terrain> terrains)
        {
            foreach (Terrain t in terrains)
            {
                Undo.RecordObject(t.gameObject, UndoName);
                t.gameObject.SetActive(false);
            }
        }

        static TerrainTile Tile(Terrain t)
        {
            TerrainData data = t.terrainData;
            int res = data.heightmapResolution;
            float[,] fractions = data.GetHeights(0, 0, res, res);   // [z, x], south row first
            var heights = new double[res * res];
            for (int r = 0; r < res; r++)
                for (int c = 0; c < res; c++) heights[r * res + c] = fractions[r, c];
            Vector3 p = t.transform.position, size = data.size;
            return new TerrainTile(t.name, p.x, p.z, size.x, size.y, size.z, res, heights, p.y);
        }

        /// <summary>A Terrain's name as a file name: a '/' or another character no file name may hold becomes '_'.</summary>
        static string AssetFileName(string name)
        {
            char[] bad = System.IO.Path.GetInvalidFileNameChars();
            var chars = name.ToCharArray();
            for (int i = 0; i < chars.Length; i++)
                if (chars[i] == '/' || chars[i] == '\\' || chars[i] == ':' || System.Array.IndexOf(bad, chars[i]) >= 0) chars[i] = '_';
            return new string(chars);
        }

        static void Refuse(string message) => EditorUtility.DisplayDialog("Convert terrain", message, "OK");

        static List<Terrain> SelectedTerrains()
        {
            var result = new List<Terrain>();
            foreach (GameObject g in Selection.gameObjects)
            {
                Terrain t = g.GetComponent<Terrain>();   // Unity's == null: in the editor a missing component is a fake-null object, which `is` would take
                if (t != null) result.Add(t);
            }
            return result;
        }
    }
}
