using System;
using System.IO;
using System.Linq;
using System.Threading;
using GregoryTerrain;
using UnityEditor;
using UnityEditor.Build;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using UnityEngine.Serialization;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Makes an n x m grid or fits one to a heightmap (Texture2D at full precision, or RAW),
    /// cancellable, optionally from a target error; error heat map; G1 by G1Builder. One Undo step a change.
    /// </summary>
    internal sealed class PatchGridWindow : EditorWindow
    {
        /// <summary>Patches a side the window offers; GpuLayout.CheckSize holds the GPU's own limit.</summary>
        internal const int MaxSide = 1024;
        /// <summary>The largest Max Size a texture import offers.</summary>
        const int MaxImportSize = 16384;

        static readonly GUIContent AssetLabel = new GUIContent("Patch grid", "The asset the buttons below change.");
        static readonly GUIContent ColumnsLabel = new GUIContent("Columns (n)", "Patches along x (1 to 1024).");
        static readonly GUIContent RowsLabel = new GUIContent("Rows (m)", "Patches along y (1 to 1024).");
        static readonly GUIContent TextureLabel = new GUIContent("Heightmap texture", "Imported readable, uncompressed, at its file's size. R16, RGBA64 (16-bit PNG), RHalf, RFloat and EXR formats keep full precision; others are read as 8-bit grey.");
        static readonly GUIContent RawFormatLabel = new GUIContent("RAW sample format", "How the RAW file stores a sample: Unity's RAW export is 16-bit unsigned (Windows = little-endian, Mac = big-endian); SRTM .hgt is signed 16-bit big-endian.");
        static readonly GUIContent RawSizeLabel = new GUIContent("RAW width x height", "Samples per row and rows. 0 x 0 reads a square file's size from its length; with one given, the other follows.");
        static readonly GUIContent RawRowsLabel = new GUIContent("RAW first row", "Which edge of the terrain the first row of the file is. By File Type: north for SRTM .hgt files, south for other RAW files (as Unity's Import Raw). North First is Unity's Flip Vertically.");
        static readonly GUIContent RawVoidLabel = new GUIContent("-32768 is no data", "Treat -32768 as a void (SRTM) and fill it from its neighbours before fitting.");
        static readonly GUIContent SampleHeightLabel = new GUIContent("Sample height (terrain units)", "Terrain height units of a full-scale sample (white, 65535), or per stored unit for signed 16-bit and float samples.");
        static readonly GUIContent MetresPerUnitLabel = new GUIContent("Metres per height unit", "World metres per height unit (Height Scale x Transform y scale), for errors in metres. From a renderer drawing this grid, else typed.");
        static readonly GUIContent TargetLabel = new GUIContent("Choose patches from a target error", "Fit with the fewest patches (rows follow the heightmap's aspect) whose error is at most the target.");
        static readonly GUIContent TargetErrorLabel = new GUIContent("Target error (m)", "The largest acceptable error, in metres.");
        static readonly GUIContent TargetKindLabel = new GUIContent("Error measured as", "Max: the worst sample. Rms: the root mean square over all samples.");

        static readonly GUIContent FixImportLabel = new GUIContent("Fix import settings", "Reimport the texture readable, uncompressed and at its file's size, so the fit reads the file's heights.");
        static readonly GUIContent SelectionLabel = new GUIContent("Selected patches", "The patches picked in the Scene view with the Sculpt tool's Select Patches mode.");
        static readonly GUIContent RefitTextureLabel = new GUIContent("Refit selection to texture", "Fit only the selected patches to the heightmap texture above (it covers the whole terrain). The border with other patches stays.");
        static readonly GUIContent RefitRawLabel = new GUIContent("Refit selection to RAW file...", "Fit only the selected patches to a RAW heightmap of the whole terrain, in the format above. The border with other patches stays.");

        [SerializeField] PatchGridAsset asset;
        [SerializeField] int columns = 5, rows = 5;
        [SerializeField] Texture2D heightmap;
        [SerializeField] RawSampleFormat rawFormat = RawSampleFormat.UInt16LittleEndian;
        [SerializeField] int rawWidth, rawHeight;
        [SerializeField] bool rawVoids;
        [SerializeField] RawRowOrder rawRowOrder = RawRowOrder.ByFileType;
        [SerializeField, FormerlySerializedAs("heightScale")] float sampleHeight = 0.1f;
        [SerializeField, FormerlySerializedAs("widthMetres")] float metresPerHeightUnit = 1000f;
        [SerializeField] bool useTarget;
        [SerializeField] float targetMetres = 1f;
        [SerializeField] FitErrorKind targetKind = FitErrorKind.Max;
        string _message;
        MessageType _messageType;
        Texture2D _errorTexture;
        string _errorLegend;

        GregoryTerrainRenderer[] _renderers;   // searched again when the hierarchy changes
        string _exrPath;                        // the EXR file _exrHas32Bits was read from (OnGUI runs every repaint)
        DateTime _exrWritten;                   // and its last write then
        bool _exrHas32Bits;
        double _unitMetres;                     // a drawing renderer's, else metresPerHeightUnit

        GregoryTerrainRenderer[] Renderers => _renderers ??= UnityEngine.Object.FindObjectsByType<GregoryTerrainRenderer>(FindObjectsSortMode.None);

        void ForgetRenderers() => _renderers = null;

        void OnEnable() => EditorApplication.hierarchyChanged += ForgetRenderers;

        void OnFocus() => ForgetRenderers();

        void DrawMetresPerHeightUnit()
        {
            GregoryTerrainRenderer drawing = asset == null ? null : Renderers.FirstOrDefault(r => r != null && r.Grid == asset);
            if (drawing == null)
            {
                metresPerHeightUnit = Mathf.Max(1e-3f, EditorGUILayout.FloatField(MetresPerUnitLabel, metresPerHeightUnit));
                _unitMetres = metresPerHeightUnit;
                return;
            }
            _unitMetres = drawing.WorldUnitsPerObjectUnit.y;
            EditorGUILayout.LabelField(MetresPerUnitLabel, new GUIContent($"{_unitMetres:G4} m (from {drawing.name})",
                $"Used instead of the {metresPerHeightUnit:G4} typed, while {drawing.name} draws this grid."));
        }

        void OnDisable()
        {
            EditorApplication.hierarchyChanged -= ForgetRenderers;
            if (_errorTexture != null) DestroyImmediate(_errorTexture);
        }

        void OnGUI()
        {
            asset = (PatchGridAsset)EditorGUILayout.ObjectField(AssetLabel, asset, typeof(PatchGridAsset), false);
            columns = Mathf.Clamp(EditorGUILayout.IntField(ColumnsLabel, columns), 1, MaxSide);
            rows = Mathf.Clamp(EditorGUILayout.IntField(RowsLabel, rows), 1, MaxSide);
            sampleHeight = EditorGUILayout.FloatField(SampleHeightLabel, sampleHeight);
            DrawMetresPerHeightUnit();
            useTarget = EditorGUILayout.Toggle(TargetLabel, useTarget);
            if (useTarget)
            {
                targetMetres = Mathf.Max(1e-6f, EditorGUILayout.FloatField(TargetErrorLabel, targetMetres));
                targetKind = (FitErrorKind)EditorGUILayout.EnumPopup(TargetKindLabel, targetKind);
            }

            if (asset == null)
            {
                EditorGUILayout.HelpBox("Pick a Patch Grid asset (Assets > Create > Gregory Terrain > Patch Grid).", MessageType.Info);
                return;
            }
            if (!asset.IsValid) EditorGUILayout.HelpBox(asset.ValidationError, MessageType.Error);

            if (GUILayout.Button(new GUIContent("Make flat grid", "Replace the grid with a flat n x m grid at height 0."))) MakeFlat();

            EditorGUILayout.Space();
            heightmap = (Texture2D)EditorGUILayout.ObjectField(TextureLabel, heightmap, typeof(Texture2D), false);
            TextureImporter importer = null;
            string importProblem = heightmap != null ? ImportProblem(heightmap, out importer, out _, out _) : null;
            if (importProblem != null)
            {
                EditorGUILayout.HelpBox(importProblem, MessageType.Warning);
                // Reimporting reloads the texture: leave this GUI pass, whose layout no longer holds.
                if (importer != null && GUILayout.Button(FixImportLabel)) { FixImport(heightmap); GUIUtility.ExitGUI(); }
            }
            using (new EditorGUI.DisabledScope(heightmap == null || importProblem != null))
                if (GUILayout.Button(new GUIContent("Fit to texture", "Least-squares fit of a G1 grid to every texel (Core's HeightmapFitter)."))) FitTexture();

            EditorGUILayout.Space();
            rawFormat = (RawSampleFormat)EditorGUILayout.EnumPopup(RawFormatLabel, rawFormat);
            rawWidth = Mathf.Max(0, EditorGUILayout.IntField(RawSizeLabel, rawWidth));
            rawHeight = Mathf.Max(0, EditorGUILayout.IntField(" ", rawHeight));
            rawRowOrder = (RawRowOrder)EditorGUILayout.EnumPopup(RawRowsLabel, rawRowOrder);
            rawVoids = EditorGUILayout.Toggle(RawVoidLabel, rawVoids);
            // A RAW button's modal file dialog leaves this GUI pass's layout stale: exit it, as Unity's windows do.
            if (GUILayout.Button(new GUIContent("Fit to RAW file...", "Least-squares fit to a headerless RAW heightmap in the format above."))) { FitRaw(); GUIUtility.ExitGUI(); }

            EditorGUILayout.Space();
            PatchRect? selection = PatchGridSculptTool.SelectionOf(asset);
            EditorGUILayout.LabelField(SelectionLabel, new GUIContent(selection is PatchRect sel ? $"columns {sel.I0} to {sel.I1}, rows {sel.J0} to {sel.J1}" : "none (Sculpt tool, Select Patches)"));
            using (new EditorGUI.DisabledScope(!asset.IsValid || selection == null))
            {
                using (new EditorGUI.DisabledScope(heightmap == null || importProblem != null))
                    if (GUILayout.Button(RefitTextureLabel)) RefitTexture();
                if (GUILayout.Button(RefitRawLabel)) { RefitRaw(); GUIUtility.ExitGUI(); }
            }

            EditorGUILayout.Space();
            using (new EditorGUI.DisabledScope(!asset.IsValid))
                if (GUILayout.Button(new GUIContent("Enforce G1", "Set the interior control points so neighbouring patches join with a continuous tangent plane."))) EnforceG1();

            if (_message != null) EditorGUILayout.HelpBox(_message, _messageType);
            if (_errorTexture != null)
            {
                EditorGUILayout.HelpBox(_errorLegend, MessageType.None);
                EditorGUI.DrawPreviewTexture(GUILayoutUtility.GetRect(64, 512, 64, 512), _errorTexture);
            }
        }

        void MakeFlat()
        {
            Apply("Make flat grid", PatchGrid.CreateFlat(columns, rows));
        }

        void FitTexture()
        {
            if (ReadTexture(out double[] heights, out string source)) Fit(heights, heightmap.width, heightmap.height, source);
        }

        void RefitTexture()
        {
            if (ReadTexture(out double[] heights, out string source)) Refit(heights, heightmap.width, heightmap.height, source);
        }

        /// <summary>The texture's heights (scaled) and a name for messages; false, with the reason reported, when it cannot be read.</summary>
        bool ReadTexture(out double[] heights, out string source)
        {
            heights = null;
            source = null;
            string problem = ImportProblem(heightmap, out _, out _, out _);
            if (problem != null)
            {
                Report(problem + " The grid was not changed.", MessageType.Error);
                return false;
            }
            string precision;
            if (TryTexelFormat(heightmap.format, out HeightTexelFormat texel))
            {
                try { heights = TextureHeights.Decode(heightmap.name, heightmap.GetRawTextureData(), heightmap.width, heightmap.height, texel); }
                catch (ArgumentException e) { Report(e.Message, MessageType.Error); return false; }
                precision = $"{heightmap.format}, full precision";
            }
            else
            {
                Color[] pixels = heightmap.GetPixels();
                heights = new double[pixels.Length];
                for (int k = 0; k < pixels.Length; k++) heights[k] = pixels[k].grayscale;
                precision = $"{heightmap.format} read as grey: 8 bits at most; import 16-bit PNGs as R16 and EXRs as RFloat or RHalf to keep their precision";
            }
            for (int k = 0; k < heights.Length; k++) heights[k] *= sampleHeight;
            source = $"'{heightmap.name}' ({precision})";
            return true;
        }

        /// <summary>
        /// Why the texture as imported does not hold its file's heights (Core's TextureHeights.ImportProblem),
        /// or null. The file's size comes from its importer; a texture with no file of its own is its own source.
        /// </summary>
        string ImportProblem(Texture2D texture, out TextureImporter importer, out int sourceWidth, out int sourceHeight)
        {
            importer = AssetImporter.GetAtPath(AssetDatabase.GetAssetPath(texture)) as TextureImporter;
            sourceWidth = texture.width; sourceHeight = texture.height;
            importer?.GetSourceTextureWidthAndHeight(out sourceWidth, out sourceHeight);
            return TextureHeights.ImportProblem(texture.name, sourceWidth, sourceHeight, texture.width, texture.height,
                texture.format.ToString(), GraphicsFormatUtility.IsCompressedFormat(texture.format), texture.isReadable,
                FileHas32BitChannels(importer));
        }

        /// <summary>Whether the importer's file is an EXR of 32-bit channels (its header, read again when the file changes).</summary>
        bool FileHas32BitChannels(TextureImporter importer)
        {
            string path = importer == null ? null : importer.assetPath;
            if (path == null || !path.EndsWith(".exr", StringComparison.OrdinalIgnoreCase)) return false;
            string full = Path.GetFullPath(path);   // a Packages/ path resolves to the package's folder
            DateTime written = File.Exists(full) ? File.GetLastWriteTimeUtc(full) : default;
            if (full == _exrPath && written == _exrWritten) return _exrHas32Bits;
            byte[] header = new byte[64 * 1024];
            int read = 0;
            try
            {
                using (var f = File.OpenRead(full)) read = f.Read(header, 0, header.Length);
            }
            catch (IOException) { }
            catch (UnauthorizedAccessException) { }
            Array.Resize(ref header, read);
            _exrPath = full;
            _exrWritten = written;
            _exrHas32Bits = TextureHeights.ExrHas32BitChannels(header) == true;
            return _exrHas32Bits;
        }

        /// <summary>
        /// The platform settings the fix writes besides the default ones: a 32-bit EXR gets RFloat on the
        /// Default tab (Unity's default import is half: 11 significant bits). An active-platform
        /// override wins over the Default tab: dropped when it compresses the heights or would not read
        /// such an EXR at 32 bits, else kept (a chosen R16, say) with Max Size raised to the file's.
        /// </summary>
        void FixPlatformSettings(TextureImporter importer, bool compressed, int side)
        {
            bool wide = FileHas32BitChannels(importer);
            if (wide)
            {
                TextureImporterPlatformSettings all = importer.GetDefaultPlatformTextureSettings();
                all.format = TextureImporterFormat.RFloat;
                importer.SetPlatformTextureSettings(all);
            }
            string platform = NamedBuildTarget.FromBuildTargetGroup(BuildPipeline.GetBuildTargetGroup(EditorUserBuildSettings.activeBuildTarget)).TargetName;
            TextureImporterPlatformSettings active = importer.GetPlatformTextureSettings(platform);
            if (!active.overridden) return;
            bool reads32 = active.format == TextureImporterFormat.RFloat || active.format == TextureImporterFormat.RGBAFloat;
            if (compressed || (wide && !reads32)) active.overridden = false;
            else while (active.maxTextureSize < side) active.maxTextureSize *= 2;
            importer.SetPlatformTextureSettings(active);
        }

        /// <summary>Imports the texture so that it holds its file's heights: readable, uncompressed, at the file's size.</summary>
        void FixImport(Texture2D texture)
        {
            ImportProblem(texture, out TextureImporter importer, out int w, out int h);
            int side = Math.Max(w, h);
            if (side > MaxImportSize)
            {
                Report($"'{texture.name}' is {w} x {h}: Unity imports textures up to {MaxImportSize} a side. Export it as RAW and use Fit to RAW file.", MessageType.Error);
                return;
            }
            importer.isReadable = true;
            importer.textureCompression = TextureImporterCompression.Uncompressed;
            importer.npotScale = TextureImporterNPOTScale.None;
            while (importer.maxTextureSize < side) importer.maxTextureSize *= 2;
            FixPlatformSettings(importer, GraphicsFormatUtility.IsCompressedFormat(texture.format), side);
            importer.SaveAndReimport();
            Report($"'{texture.name}' reimported readable, uncompressed{(FileHas32BitChannels(importer) ? " (RFloat)" : "")}, at {w} x {h}.", MessageType.Info);
        }

        static bool TryTexelFormat(TextureFormat format, out HeightTexelFormat texel)
        {
            switch (format)
            {
                case TextureFormat.R16: texel = HeightTexelFormat.R16; return true;
                case TextureFormat.RGBA64: texel = HeightTexelFormat.RGBA64; return true;
                case TextureFormat.RHalf: texel = HeightTexelFormat.RHalf; return true;
                case TextureFormat.RGBAHalf: texel = HeightTexelFormat.RGBAHalf; return true;
                case TextureFormat.RFloat: texel = HeightTexelFormat.RFloat; return true;
                case TextureFormat.RGBAFloat: texel = HeightTexelFormat.RGBAFloat; return true;
                default: texel = default; return false;
            }
        }

        void FitRaw()
        {
            if (ReadRaw(out double[] heights, out int w, out int h, out string source)) Fit(heights, w, h, source);
        }

        void RefitRaw()
        {
            if (ReadRaw(out double[] heights, out int w, out int h, out string source)) Refit(heights, w, h, source);
        }

        /// <summary>A RAW file's heights (scaled), its size and a name for messages; false when cancelled or unreadable (reported).</summary>
        bool ReadRaw(out double[] heights, out int w, out int h, out string source)
        {
            heights = null;
            source = null;
            w = rawWidth; h = rawHeight;
            string path = EditorUtility.OpenFilePanel("RAW heightmap", "", "");
            if (string.IsNullOrEmpty(path)) return false;
            string name = Path.GetFileName(path);
            try
            {
                byte[] bytes = File.ReadAllBytes(path);
                heights = RawHeightmap.ReadSouthFirst(name, bytes, rawFormat, rawRowOrder, ref w, ref h, rawVoids ? RawHeightmap.SrtmVoid : (int?)null);
            }
            catch (IOException e) { Report($"{name}: {e.Message}", MessageType.Error); return false; }
            catch (ArgumentException e) { Report(e.Message, MessageType.Error); return false; }
            bool unsigned16 = rawFormat == RawSampleFormat.UInt16LittleEndian || rawFormat == RawSampleFormat.UInt16BigEndian;
            double scale = unsigned16 ? sampleHeight / 65535.0 : sampleHeight;
            for (int k = 0; k < heights.Length; k++) heights[k] *= scale;
            source = $"{name} ({w} x {h}, {rawFormat}, first row {(RawHeightmap.FirstRowIsNorth(name, rawRowOrder) ? "north" : "south")})";
            return true;
        }

        /// <summary>
        /// Refits the Scene view's patch selection to a heightmap of the whole terrain, cancellable; a
        /// cancel or an error leaves the asset as it was. One undo step of the changed blocks only.
        /// </summary>
        void Refit(double[] heights, int width, int height, string source)
        {
            if (!(PatchGridSculptTool.SelectionOf(asset) is PatchRect selection))
            {
                Report("Select patches first: Sculpt tool in the Scene view, mode Select Patches, drag over the terrain.", MessageType.Warning);
                return;
            }
            int voids;
            try { voids = HeightmapVoids.Fill(heights, width, height); }
            catch (ArgumentException e) { Report($"{source}: {e.Message}", MessageType.Error); return; }
            using var cancel = new CancellationTokenSource();
            var progress = new CancelableProgressBar($"Refitting {selection} to {source}", cancel);
            try
            {
                RegionFitResult fit = PatchRegionFit.Fit(asset.ToPatchGrid(), selection, heights, width, height, progress, cancel.Token);
                PatchGridAssetUndo.ApplyEdit(asset, fit.Edit, $"Refit selection to {source}");
                string filled = voids > 0 ? $" {voids} void samples were filled from their neighbours first." : "";
                Report($"Refitted {selection} ({fit.Edit.Patches.Length} patches changed) to {source}: max error {fit.MaxError * _unitMetres:G3} m, RMS {fit.RmsError * _unitMetres:G3} m over the selection. The border with the other patches was kept.{filled}", MessageType.Info);
            }
            catch (OperationCanceledException) { Report("Refit cancelled; the grid was not changed.", MessageType.Warning); }
            catch (ArgumentException e) { Report($"{source}: {e.Message} The grid was not changed.", MessageType.Error); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        /// <summary>Fills voids, runs the fitter with a cancellable progress bar; a cancel or error leaves the asset as it was.</summary>
        void Fit(double[] heights, int width, int height, string source)
        {
            int voids;
            try { voids = HeightmapVoids.Fill(heights, width, height); }
            catch (ArgumentException e) { Report($"{source}: {e.Message}", MessageType.Error); return; }
            using var cancel = new CancellationTokenSource();
            string what = useTarget ? $"Fitting to {targetKind} error {targetMetres:G3} m" : $"Fitting {columns} x {rows} patches";
            var progress = new CancelableProgressBar($"{what}: {source}", cancel);
            try
            {
                // Texture rows run bottom-up and RAW rows come south first (ReadSouthFirst): sample (c, r)
                // lands at (c / (W-1), r / (H-1)) of the unit square, y = 0 the south edge, either way.
                HeightmapFit fit = useTarget
                    ? HeightmapFitter.FitToTarget(heights, width, height, targetMetres / _unitMetres, targetKind, MaxSide, progress, cancel.Token)
                    : HeightmapFitter.Fit(heights, width, height, columns, rows, progress, cancel.Token);
                Apply($"Fit patch grid to {source}", fit.Grid);
                ShowErrorMap(fit);
                string filled = voids > 0 ? $" {voids} void samples were filled from their neighbours first." : "";
                Report($"Fitted {fit.Grid.Columns} x {fit.Grid.Rows} patches to {source}: max error {fit.MaxError * _unitMetres:G3} m, RMS {fit.RmsError * _unitMetres:G3} m ({fit.MaxError:G3} and {fit.RmsError:G3} terrain units).{filled}"
                    + (useTarget && (targetKind == FitErrorKind.Max ? fit.MaxError : fit.RmsError) * _unitMetres > targetMetres ? $" The target was not reached at {MaxSide} columns." : ""),
                    MessageType.Info);
            }
            catch (OperationCanceledException) { Report("Fit cancelled; the grid was not changed.", MessageType.Warning); }
            catch (ArgumentException e) { Report($"{source}: {e.Message}", MessageType.Error); }
            finally { EditorUtility.ClearProgressBar(); }
        }

        /// <summary>The fit's error map as a texture under the message, red at the fit's max error.</summary>
        void ShowErrorMap(HeightmapFit fit)
        {
            if (_errorTexture != null) DestroyImmediate(_errorTexture);
            _errorTexture = null;
            if (!(fit.MaxError > 0)) return;
            FitErrorMap map = fit.ErrorMap;
            _errorTexture = new Texture2D(map.Width, map.Height, TextureFormat.RGBA32, false);
            _errorTexture.LoadRawTextureData(map.ToRgba32(fit.MaxError));
            _errorTexture.Apply();
            _errorLegend = $"Error map ({map.Width} x {map.Height} cells, each the worst sample in it): black 0, blue, yellow, red {fit.MaxError * _unitMetres:G3} m.";
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
    }
}
