using System;
using System.IO;
using System.Threading;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Authoring window: makes an n x m grid, fits it to a heightmap (a readable Texture2D or a
    /// 16-bit little-endian RAW file) with a cancellable progress bar, and enforces G1 with Core's
    /// G1Builder. Every change to the asset is one undo step.
    /// </summary>
    public sealed class PatchGridWindow : EditorWindow
    {
        static readonly GUIContent AssetLabel = new GUIContent("Patch grid", "The asset the buttons below change.");
        static readonly GUIContent ColumnsLabel = new GUIContent("Columns (n)", "Patches along x.");
        static readonly GUIContent RowsLabel = new GUIContent("Rows (m)", "Patches along y.");
        static readonly GUIContent TextureLabel = new GUIContent("Heightmap texture", "Grey value = height; the texture must have Read/Write enabled.");
        static readonly GUIContent RawSizeLabel = new GUIContent("RAW width x height", "Samples per row and rows of the 16-bit little-endian RAW file.");
        static readonly GUIContent HeightScaleLabel = new GUIContent("Height scale", "Terrain units of height for a full-scale sample (1.0 grey or 65535).");

        [SerializeField] PatchGridAsset asset;
        [SerializeField] int columns = 5, rows = 5;
        [SerializeField] Texture2D heightmap;
        [SerializeField] int rawWidth = 513, rawHeight = 513;
        [SerializeField] float heightScale = 0.1f;
        string _message;
        MessageType _messageType;

        void OnGUI()
        {
            asset = (PatchGridAsset)EditorGUILayout.ObjectField(AssetLabel, asset, typeof(PatchGridAsset), false);
            columns = Mathf.Clamp(EditorGUILayout.IntField(ColumnsLabel, columns), 1, 256);
            rows = Mathf.Clamp(EditorGUILayout.IntField(RowsLabel, rows), 1, 256);
            heightScale = EditorGUILayout.FloatField(HeightScaleLabel, heightScale);

            if (asset == null)
            {
                EditorGUILayout.HelpBox("Pick a Patch Grid asset (Assets > Create > Gregory Terrain > Patch Grid).", MessageType.Info);
                return;
            }
            if (!asset.IsValid) EditorGUILayout.HelpBox(asset.ValidationError, MessageType.Error);

            if (GUILayout.Button(new GUIContent("Make flat grid", "Replace the grid with a flat n x m grid at height 0."))) MakeFlat();

            EditorGUILayout.Space();
            heightmap = (Texture2D)EditorGUILayout.ObjectField(TextureLabel, heightmap, typeof(Texture2D), false);
            using (new EditorGUI.DisabledScope(heightmap == null))
                if (GUILayout.Button(new GUIContent("Fit to texture", "Least-squares fit of the n x m grid to the texture's grey values (Core's HeightmapFitter)."))) FitTexture();

            EditorGUILayout.Space();
            rawWidth = Mathf.Max(2, EditorGUILayout.IntField(RawSizeLabel, rawWidth));
            rawHeight = Mathf.Max(2, EditorGUILayout.IntField(" ", rawHeight));
            if (GUILayout.Button(new GUIContent("Fit to RAW file...", "Fit to a 16-bit little-endian RAW heightmap of the size above."))) FitRaw();

            EditorGUILayout.Space();
            using (new EditorGUI.DisabledScope(!asset.IsValid))
                if (GUILayout.Button(new GUIContent("Enforce G1", "Set the interior control points so neighbouring patches join with a continuous tangent plane (eq. 7-9)."))) EnforceG1();

            if (_message != null) EditorGUILayout.HelpBox(_message, _messageType);
        }

        void MakeFlat()
        {
            Apply("Make flat grid", PatchGrid.CreateFlat(columns, rows));
        }

        void FitTexture()
        {
            if (!heightmap.isReadable)
            {
                Report($"'{heightmap.name}' is not readable: enable Read/Write in its import settings.", MessageType.Error);
                return;
            }
            Color[] pixels = heightmap.GetPixels();
            var heights = new double[pixels.Length];
            for (int k = 0; k < pixels.Length; k++) heights[k] = pixels[k].grayscale * heightScale;
            Fit(heights, heightmap.width, heightmap.height, heightmap.name);
        }

        void FitRaw()
        {
            string path = EditorUtility.OpenFilePanel("16-bit RAW heightmap", "", "raw");
            if (string.IsNullOrEmpty(path)) return;
            byte[] bytes = File.ReadAllBytes(path);
            long expected = 2L * rawWidth * rawHeight;
            if (bytes.Length != expected)
            {
                Report($"{Path.GetFileName(path)} has {bytes.Length} bytes; {rawWidth} x {rawHeight} 16-bit samples need {expected}. Check the size.", MessageType.Error);
                return;
            }
            var heights = new double[rawWidth * rawHeight];
            for (int k = 0; k < heights.Length; k++)
                heights[k] = (bytes[2 * k] | (bytes[2 * k + 1] << 8)) / 65535.0 * heightScale;   // little-endian
            Fit(heights, rawWidth, rawHeight, Path.GetFileName(path));
        }

        /// <summary>Runs the fitter with a cancellable progress bar; a cancel leaves the asset as it was.</summary>
        void Fit(double[] heights, int width, int height, string source)
        {
            using var cancel = new CancellationTokenSource();
            var progress = new ProgressBar($"Fitting {columns} x {rows} patches to {source}", cancel);
            try
            {
                // Texture rows run bottom-up and RAW rows as stored: sample (c, r) lands at
                // (c / (W-1), r / (H-1)) of the unit square either way (HeightmapFitter's convention).
                HeightmapFit fit = HeightmapFitter.Fit(heights, width, height, columns, rows, progress, cancel.Token);
                Apply($"Fit patch grid to {source}", fit.Grid);
                Report($"Fitted {columns} x {rows} patches to {source}: max error {fit.MaxError:G3}, RMS {fit.RmsError:G3} (terrain units).", MessageType.Info);
            }
            catch (OperationCanceledException) { Report("Fit cancelled; the grid was not changed.", MessageType.Warning); }
            catch (ArgumentException e) { Report(e.Message, MessageType.Error); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        void EnforceG1()
        {
            try
            {
                PatchGrid grid = asset.ToPatchGrid();   // a copy: MakeG1 changes it in place, or throws and changes nothing
                G1Builder.MakeG1(grid);
                Apply("Enforce G1", grid);
                Report($"Enforce G1: max normal angle across shared edges now {ContinuityMeasure.MaxNormalAngleDegrees(grid):G3} degrees.", MessageType.Info);
            }
            catch (ArgumentException e) { Report(e.Message, MessageType.Error); }
        }

        void Apply(string undoName, PatchGrid grid)
        {
            PatchGridAssetUndo.SetGrid(asset, grid, undoName);
            Report($"{undoName}: {grid.Columns} x {grid.Rows} patches.", MessageType.Info);
        }

        void Report(string message, MessageType type) { _message = message; _messageType = type; Repaint(); }

        /// <summary>
        /// The fitter's progress reports go to the editor's progress bar; its Cancel button cancels
        /// the token. The fitter reports from the calling (main) thread, which the bar requires.
        /// </summary>
        sealed class ProgressBar : IProgress<float>
        {
            readonly string _title;
            readonly CancellationTokenSource _cancel;
            public ProgressBar(string title, CancellationTokenSource cancel) { _title = title; _cancel = cancel; }
            public void Report(float value)
            {
                if (EditorUtility.DisplayCancelableProgressBar(_title, $"{value:P0}", value)) _cancel.Cancel();
            }
        }
    }
}
