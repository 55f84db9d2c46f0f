using System;
using System.IO;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>Inspector of a patch grid: summary, validation, G1 measure, JSON import/export.</summary>
    [CustomEditor(typeof(PatchGridAsset))]
    internal sealed class PatchGridAssetEditor : Editor
    {
        static readonly GUIContent MeasureLabel = new GUIContent("Measure G1", "Largest position gap and normal angle across shared patch edges (Core's ContinuityMeasure).");
        static readonly GUIContent ImportLabel = new GUIContent("Import JSON...", "Replace the grid with one read from a JSON file. A file that fails to parse changes nothing.");
        static readonly GUIContent ExportLabel = new GUIContent("Export JSON...", "Write the grid to a JSON file (Core's PatchGridJson format).");
        string _measure;

        public override void OnInspectorGUI()
        {
            var asset = (PatchGridAsset)target;
            EditorGUILayout.LabelField("Patches", $"{asset.Columns} x {asset.Rows} = {asset.PatchCount}");
            if (!asset.IsValid)
                EditorGUILayout.HelpBox(asset.ValidationError, MessageType.Error);
            else
                EditorGUILayout.HelpBox("Valid grid. Edit it with Window > Gregory Terrain > Patch Grid, or move control points in the Scene view.", MessageType.Info);

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
                Undo.RecordObject(asset, "Import patch grid");
                asset.SetGrid(grid);
                EditorUtility.SetDirty(asset);
            }
            catch (Exception e) when (e is FormatException || e is ArgumentException || e is IOException)
            {
                EditorUtility.DisplayDialog("Import failed", $"{Path.GetFileName(path)}: {e.Message}\nThe grid was not changed.", "OK");
            }
        }
    }
}
