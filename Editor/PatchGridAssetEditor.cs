using System;
using System.Collections.Generic;
using System.IO;
using System.Threading;
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
        static readonly GUIContent UpgradeLabel = new GUIContent("Move to blocks", "Move the control points into block sub-assets now, bit for bit (one undo step). Edits do it by themselves.");
        string _measure;
        List<string> _warnings;
        int _warningsVersion;

        public override void OnInspectorGUI()
        {
            var asset = (PatchGridAsset)target;
            EditorGUILayout.LabelField("Patches", $"{asset.Columns} x {asset.Rows} = {asset.PatchCount}");
            if (!asset.IsValid)
                EditorGUILayout.HelpBox(asset.ValidationError, MessageType.Error);
            else
                EditorGUILayout.HelpBox("Valid grid. Edit it with Window > Gregory Terrain > Patch Grid, or move control points in the Scene view.", MessageType.Info);
            if (asset.IsValid && _warningsVersion != asset.Version)
            {
                _warnings = PatchGridGeometry.Warnings(asset.ToPatchGrid());
                _warningsVersion = asset.Version;
            }
            if (asset.IsValid && _warnings.Count > 0)
                EditorGUILayout.HelpBox("Geometry that will not draw sensibly:\n" + string.Join("\n", _warnings), MessageType.Warning);

            if (asset.HasLegacyLayout && asset.IsValid)
            {
                EditorGUILayout.HelpBox("This grid keeps its control points in the older single array. It loads and draws as is; its first edit moves them into blocks (only the blocks an edit touches are recorded for Undo).", MessageType.Info);
                if (GUILayout.Button(UpgradeLabel)) PatchGridAssetUndo.MoveLegacyDataToBlocks(asset, "Move patch grid to blocks");
            }
            using (new EditorGUI.DisabledScope(!asset.IsValid))
            {
                if (GUILayout.Button(MeasureLabel))
                {
                    _measure = Measure(asset.ToPatchGrid());
                }
                if (_measure != null) EditorGUILayout.HelpBox(_measure, MessageType.None);
                // A modal dialog leaves this GUI pass's layout stale: exit it, as Unity's inspectors do.
                if (GUILayout.Button(ExportLabel)) { Export(asset); GUIUtility.ExitGUI(); }
            }
            if (GUILayout.Button(ImportLabel)) { Import(asset); GUIUtility.ExitGUI(); }

            EditorGUILayout.Space();
            DrawDefaultInspector();
        }

        static string Measure(PatchGrid grid)
        {
            var cancel = new CancellationTokenSource();
            try
            {
                var bar = new CancelableProgressBar("Measure G1", cancel, "Sampling shared patch edges...");
                ContinuityResult r = ContinuityMeasure.Measure(grid, ContinuityMeasure.DefaultSamplesPerEdge, bar.Report, cancel.Token);
                return $"max position gap {r.MaxPositionGap:G3}, max normal angle {r.MaxNormalAngleDegrees:G3} degrees " +
                       $"({ContinuityMeasure.DefaultSamplesPerEdge} samples per shared edge)";
            }
            catch (OperationCanceledException) { return "G1 measure cancelled."; }
            finally { EditorUtility.ClearProgressBar(); cancel.Dispose(); }
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
                PatchGrid grid = PatchGridJson.ReadFile(path);     // parse first: nothing recorded on failure
                PatchGridAssetUndo.SetGrid(asset, grid, "Import patch grid");
            }
            catch (Exception e) when (e is FormatException || e is ArgumentException || e is IOException || e is UnauthorizedAccessException)
            {
                EditorUtility.DisplayDialog("Import failed", $"{Path.GetFileName(path)}: {e.Message}\nThe grid was not changed.", "OK");
            }
        }
    }
}
