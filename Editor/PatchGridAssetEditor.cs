using System;
using System.IO;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>Inspector of a patch grid: summary, validation, G1 measure, JSON import/export.</summary>
    [CustomEditor(typeof(PatchGridAsset))]
    public sealed class PatchGridAssetEditor : Editor
    {
        static readonly GUIContent MeasureLabel = new GUIContent("Measure G1", "Largest position gap and normal angle across shared patch edges (Core's ContinuityMeasure).");
        static readonly GUIContent ImportLabel = new GUIContent("Import JSON...", "Replace the grid with one read from a JSON file. A file that fails to parse changes nothing.");
        static readonly GUIContent ExportLabel = new GUIContent("Export JSON...", "Write the grid to a JSON file (Core's PatchGridJson format).");
        static readonly GUIContent UpgradeLabel = new GUIContent("Move to blocks", "Move the control points into block sub-assets now, bit for bit (one undo step). Edits do it by themselves.");
        string _measure;

        public override void OnInspectorGUI()
        {
            var asset = (PatchGridAsset)target;
            EditorGUILayout.LabelField("Patches", $"{asset.Columns} x {asset.Rows} = {asset.PatchCount}");
            if (!asset.IsValid)
                EditorGUILayout.HelpBox(asset.ValidationError, MessageType.Error);
            else
                EditorGUILayout.HelpBox("Valid grid. Edit it with Window > Gregory Terrain > Patch Grid, or move control points in the Scene view.", MessageType.Info);

            if (asset.HasLegacyLayout && asset.IsValid)
            {
                EditorGUILayout.HelpBox("This grid keeps its control points in the older single array. It loads and draws as is; its first edit moves them into blocks (only the blocks an edit touches are recorded for Undo).", MessageType.Info);
                if (GUILayout.Button(UpgradeLabel)) PatchGridAssetUndo.MoveLegacyDataToBlocks(asset, "Move patch grid to blocks");
            }
            using (new EditorGUI.DisabledScope(!asset.IsValid))
            {
                if (GUILayout.Button(MeasureLabel))
                {
                    PatchGrid grid = asset.ToPatchGrid();
                    double gap = ContinuityMeasure.MaxPositionGap(grid);
                    double angle = ContinuityMeasure.MaxNormalAngleDegrees(grid);
                    _measure = $"max position gap {gap:G3}, max normal angle {angle:G3} degrees " +
                               $"({ContinuityMeasure.DefaultSamplesPerEdge} samples per shared edge)";
                }
                if (_measure != null) EditorGUILayout.HelpBox(_measure, MessageType.None);
                if (GUILayout.Button(ExportLabel)) Export(asset);
            }
            if (GUILayout.Button(ImportLabel)) Import(asset);

            EditorGUILayout.Space();
            DrawDefaultInspector();
        }

        static void Export(PatchGridAsset asset)
        {
            string path = EditorUtility.SaveFilePanel("Export patch grid", "", asset.name + ".json", "json");
            if (string.IsNullOrEmpty(path)) return;
            File.WriteAllText(path, asset.ExportJson());
        }

        static void Import(PatchGridAsset asset)
        {
            string path = EditorUtility.OpenFilePanel("Import patch grid", "", "json");
            if (string.IsNullOrEmpty(path)) return;
            try
            {
                string json = File.ReadAllText(path);
                PatchGrid grid = PatchGridJson.Read(json);     // parse first: nothing recorded on failure
                PatchGridAssetUndo.SetGrid(asset, grid, "Import patch grid");
            }
            catch (Exception e) when (e is FormatException || e is ArgumentException || e is IOException)
            {
                EditorUtility.DisplayDialog("Import failed", $"{Path.GetFileName(path)}: {e.Message}\nThe grid was not changed.", "OK");
            }
        }
    }
}
