using System;
using System.Globalization;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// The terrain's GPU inputs as Core holds them: the three buffers <see cref="GpuLayout"/> packs and
    /// the <see cref="TerrainParams"/> constants. Mirrors <c>Shaders/Terrain/TerrainInputs.hlsl</c> and the
    /// buffer reads of <c>Shaders/Grid/PatchGrid.hlsl</c>, same names, on exactly the floats they read.
    /// Immutable apart from <see cref="Params"/> (<see cref="WithParams"/>).
    /// </summary>
    internal sealed class TerrainInputs
    {
        /// <summary>_ControlPoints: the bytes of one <see cref="GregoryPatchRecord"/> per patch as floats, patch p at float index <c>80 p</c>: (P - R_p, w), w of slots 0..2 = R_p (<see cref="GpuLayout"/>).</summary>
        public float[] ControlPoints { get; }
        /// <summary>_Regions: (a, b, e, f) per patch.</summary>
        public float[] Regions { get; }
        /// <summary>_GridLines: hi parts xLines[0..n], yLines[0..m], then the lo parts in the same order.</summary>
        public float[] GridLines { get; }
        /// <summary>The eleven float4 constants (binding 0).</summary>
        public TerrainParams Params { get; }

        /// <summary>
        /// Takes packed buffers as they are (no copy). Checks that their sizes agree with
        /// <c>Params.gridSize</c> (n, m), that the grid lines' hi parts are finite and strictly increasing
        /// and that their lo parts are finite.
        /// </summary>
        public TerrainInputs(float[] controlPoints, float[] regions, float[] gridLines, TerrainParams parameters)
        {
            if (controlPoints == null) throw new ArgumentNullException(nameof(controlPoints));
            if (regions == null) throw new ArgumentNullException(nameof(regions));
            if (gridLines == null) throw new ArgumentNullException(nameof(gridLines));
            float n = parameters.gridSize.x, m = parameters.gridSize.y;
            if (!(n >= 1f && m >= 1f) || n != GMath.floor(n) || m != GMath.floor(m) || (double)n * m > GpuLayout.MaxPatches)
                throw new ArgumentException(Invariant($"parameters.gridSize ({n:R}, {m:R}) must be whole numbers >= 1 with n * m <= 2^24"), "parameters.gridSize");
            long patches = (long)n * (long)m;
            if (controlPoints.LongLength != patches * GpuLayout.ControlPointFloatsPerPatch)
                throw new ArgumentException(Invariant($"controlPoints.Length ({controlPoints.LongLength}) must be {patches * GpuLayout.ControlPointFloatsPerPatch} for {n} x {m} patches"), nameof(controlPoints));
            if (regions.LongLength != patches * GpuLayout.RegionFloatsPerPatch)
                throw new ArgumentException(Invariant($"regions.Length ({regions.LongLength}) must be {patches * GpuLayout.RegionFloatsPerPatch} for {n} x {m} patches"), nameof(regions));
            long lines = (long)n + 1 + (long)m + 1;
            if (gridLines.LongLength != 2 * lines)
                throw new ArgumentException(Invariant($"gridLines.Length ({gridLines.LongLength}) must be {2 * lines} (hi and lo parts of {lines} lines) for {n} x {m} patches"), nameof(gridLines));
            for (int k = 0; k < lines; k++)
            {
                bool first = k == 0 || k == (int)n + 1;
                if (!GMath.isfinite(gridLines[k]) || (!first && !(gridLines[k] > gridLines[k - 1])))
                    throw new ArgumentException(Invariant($"gridLines[{k}] ({gridLines[k]:R}) must be finite and greater than the line before it"), nameof(gridLines));
                float lo = gridLines[lines + k];
                if (!GMath.isfinite(lo) || Math.Abs(lo) > Math.Abs(gridLines[k]) * 1e-6f)
                    throw new ArgumentException(Invariant($"gridLines[{lines + k}] ({lo:R}), the lo part of line {k} ({gridLines[k]:R}), must be finite and below the hi part's rounding"), nameof(gridLines));
            }
            ControlPoints = controlPoints;
            Regions = regions;
            GridLines = gridLines;
            Params = parameters;
        }

        /// <summary>Packs <paramref name="grid"/> with <see cref="GpuLayout"/> (which validates it).</summary>
        public static TerrainInputs Create(PatchGrid grid, TerrainParams parameters)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (parameters.gridSize.x != grid.Columns || parameters.gridSize.y != grid.Rows)
                throw new ArgumentException(Invariant($"parameters.gridSize ({parameters.gridSize.x:R}, {parameters.gridSize.y:R}) must be the grid's ({grid.Columns}, {grid.Rows})"), "parameters.gridSize");
            return new TerrainInputs(GpuLayout.PackControlPoints(grid), GpuLayout.PackRegions(grid), GpuLayout.PackGridLines(grid), parameters);
        }

        /// <summary>
        /// The grid's buffers with constants that hold only its size: enough for the buffer reads
        /// (<see cref="FindPatch"/>, <see cref="PatchRegion"/>, <see cref="LoadGregoryPatch"/>).
        /// </summary>
        public static TerrainInputs ForGrid(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            return Create(grid, new TerrainParams { gridSize = new Float4(grid.Columns, grid.Rows, 0f, 0f) });
        }

        /// <summary>The same buffers with other constants (a new range, other settings); the snow map stays.</summary>
        public TerrainInputs WithParams(TerrainParams parameters) => new TerrainInputs(ControlPoints, Regions, GridLines, parameters) { Snow = Snow };

        /// <summary>
        /// The snow variant's extra inputs (<c>GT_SNOW</c>: <c>_SnowDepth</c> and <c>_SnowMapSize</c>),
        /// null when there is no snow. Only <see cref="TerrainKeywords.Snow"/> reads it.
        /// </summary>
        public SnowMap Snow { get; private set; }

        /// <summary>The same inputs with a snow map (null: none).</summary>
        public TerrainInputs WithSnow(SnowMap snow) => new TerrainInputs(ControlPoints, Regions, GridLines, Params) { Snow = snow };

        // --- Patch grid (TerrainInputs.hlsl) -----------------------------------------------------

        public int GridColumns() => (int)Params.gridSize.x;
        public int GridRows() => (int)Params.gridSize.y;
        public int PatchCount() => GridColumns() * GridRows();

        // --- Range ---------------------------------------------------------------------------------

        /// <summary>Width <c>g - c</c> of the drawn range, in float, as the shaders form it.</summary>
        public float RangeWidth() => Params.range.z - Params.range.x;

        // --- Tessellation --------------------------------------------------------------------------

        /// <summary>M: tiles across the range (the lattice's cells per its width when anchored).</summary>
        public float TileCount() => Params.tess.x;
        public int TileCountInt() => (int)Params.tess.x;
        /// <summary>Tiles (draw patches, cache tiles) per axis: M, or M + 1 when anchored (<see cref="TileLattice"/>).</summary>
        public int TilesAcross() => TileLattice.TilesAcross(Params);
        public float MaxTessFactor() => Params.tess.y;
        public float TargetPixelsPerSegment() => Params.tess.z;
        public float UniformTessFactor() => Params.tess.w;
        public bool UsesUniformTessFactor() => Params.tess.w > 0f;

        // --- Noise ---------------------------------------------------------------------------------

        /// <summary><c>_Noise = (amplitude, frequency, alpha, beta)</c>.</summary>
        public Float4 NoiseSettings() => Params.noise;
        public float MaxNoiseOctaves() => Params.noiseOctaves.x;

        /// <summary>The override when set, else M tiles of maxFactor segments (per-frame values only).</summary>
        public float NoiseVerticesAcross() => Params.noiseOctaves.y > 0f ? Params.noiseOctaves.y : TileCount() * MaxTessFactor();

        /// <summary>
        /// The frame's octave count as the vertex stage forms it (HLSL <c>OctaveCount(TileLayoutWidth(),
        /// NoiseVerticesAcross(), NoiseSettings(), MaxNoiseOctaves())</c>), in float:
        /// <c>clamp(1 + log2(across / (2 width frequency)) / log2(alpha), 0, N)</c>.
        /// The GPU's log2 is an approximation of its own, so the two may differ in the last bits; only
        /// the faded last octave's weight feels it.
        /// </summary>
        public float NoiseOctaveCount() => NoiseOctaveCount(Params);

        /// <summary><see cref="NoiseOctaveCount()"/> of a constant block alone (no buffers needed).</summary>
        public static float NoiseOctaveCount(TerrainParams p)
        {
            Float4 noise = p.noise;
            float across = p.noiseOctaves.y > 0f ? p.noiseOctaves.y : p.tess.x * p.tess.y;
            float ratio = across / (2f * TileLattice.LayoutWidth(p) * noise.y);
            float k = 1f + Log2(ratio) / Log2(noise.z);
            return GMath.clamp(k, 0f, p.noiseOctaves.x);
        }

        /// <summary>
        /// <c>_NoiseOctaves.z</c>: the on-screen length, in pixels, a segment may have under the
        /// continuous octave rule of the levels of detail (<see cref="NoiseOctaveCountAt"/>); 0 keeps
        /// the single-range rule (<see cref="NoiseOctaveCount()"/>) bit for bit.
        /// </summary>
        public float NoiseSegmentPixels() => Params.noiseOctaves.z;
        /// <summary>HLSL <c>PlainPathError</c>: <c>_NoiseOctaves.w</c>, 0: every vertex precise.</summary>
        public float PlainPathError() => Params.noiseOctaves.w;
        /// <summary>HLSL <c>LevelsOriginSurface</c>: <c>_OriginSurface</c>.</summary>
        public Float4 LevelsOriginSurface() => Params.originSurface;

        /// <summary>
        /// The continuous rule as the vertex stage forms it in float (HLSL <c>OctaveCountAtPixelScale</c>,
        /// Core double <see cref="OctaveNoise.OctaveCountAtPixelScale"/>): the frame's rule with the
        /// vertex spacing <c>segmentPixels / pixelsPerUnit</c> and one vertex across; all octaves at an
        /// infinite scale (at or behind the eye plane), none at 0.
        /// </summary>
        public static float NoiseOctaveCountAt(TerrainParams p, float pixelsPerUnit)
        {
            float n = p.noiseOctaves.x;
            if (!(pixelsPerUnit < float.PositiveInfinity)) return n;
            if (!(pixelsPerUnit > 0f)) return 0f;
            float spacing = p.noiseOctaves.z / pixelsPerUnit;
            float ratio = 1f / (2f * spacing * p.noise.y);
            float k = 1f + Log2(ratio) / Log2(p.noise.z);
            return GMath.clamp(k, 0f, n);
        }

        /// <summary>The noise settings as <see cref="GregoryTerrain.NoiseSettings"/> (for the Core noise functions).</summary>
        public GregoryTerrain.NoiseSettings NoiseSettingsStruct() =>
            new GregoryTerrain.NoiseSettings(Params.noise.x, Params.noise.y, Params.noise.z, Params.noise.w, (int)Params.noiseOctaves.x);

        // --- Height colour -------------------------------------------------------------------------

        public GregoryTerrain.HeightColorSettings HeightColorSettings() =>
            new GregoryTerrain.HeightColorSettings(Params.heightColor.x, Params.heightColor.y, Params.heightColor.z);

        // --- Snow (GT_SNOW only) -------------------------------------------------------------------

        /// <summary><c>_SnowMapSize = (R, 1/R, depthCap, 0)</c>; throws when there is no snow map.</summary>
        public Float4 SnowMapSize() => RequireSnow().MapSize;
        /// <summary>Largest snow depth: what the tile bounds grow by.</summary>
        public float SnowDepthCap() => RequireSnow().DepthCap;

        SnowMap RequireSnow() => Snow ?? throw new ArgumentException("Snow: the GT_SNOW inputs need a snow map (use WithSnow)", "Snow");

        // --- Buffer reads (PatchGrid.hlsl) ----------------------------------------------------------

        /// <summary>
        /// Index <c>j n + i</c> of the patch holding <paramref name="q"/>, by binary search on the float
        /// lines of <see cref="GridLines"/>: HLSL <c>FindPatch</c>, the same rule as
        /// <see cref="PatchGrid.FindPatch"/> (a point on a shared line goes to the higher index).
        /// </summary>
        public int FindPatch(Float2 q)
        {
            int n = GridColumns(), m = GridRows();
            int i = PatchGrid.FindInterval(new ReadOnlySpan<float>(GridLines, 0, n + 1), q.x);
            int j = PatchGrid.FindInterval(new ReadOnlySpan<float>(GridLines, n + 1, m + 1), q.y);
            return j * n + i;
        }

        /// <summary>Region (a, b, e, f) of a patch as the GPU holds it (the hi parts of its grid lines).</summary>
        public Float4 PatchRegion(int patch)
        {
            CheckPatch(patch);
            int o = GpuLayout.RegionFloatsPerPatch * patch;
            return new Float4(Regions[o], Regions[o + 1], Regions[o + 2], Regions[o + 3]);
        }

        /// <summary>
        /// The lo parts (a, b, e, f) of a patch's grid lines: <c>PatchRegion + PatchRegionLo</c> is the
        /// region to ~1e-16 (HLSL <c>PatchRegionLo</c>).
        /// </summary>
        public Float4 PatchRegionLo(int patch)
        {
            CheckPatch(patch);
            int n = GridColumns(), i = patch % n, j = patch / n;
            int lo = GpuLayout.GridLinesLoOffset(n, GridRows()), y = GpuLayout.YLinesOffset(n);
            return new Float4(GridLines[lo + i], GridLines[lo + y + j], GridLines[lo + i + 1], GridLines[lo + y + j + 1]);
        }

        /// <summary>The patch's reference point R_p (w of slots 0..2): the surface is R_p + the evaluation of <see cref="LoadGregoryPatch"/>'s points.</summary>
        public Float3 PatchReference(int patch)
        {
            CheckPatch(patch);
            ref readonly GregoryPatchRecord r = ref Records()[patch];
            return new Float3(r[0].w, r[1].w, r[2].w);
        }

        /// <summary>The 20 control points of a patch relative to its reference point (slot order) into <paramref name="cp"/>.</summary>
        public void LoadGregoryPatch(int patch, Span<Float3> cp)
        {
            CheckPatch(patch);
            if (cp.Length != GregoryPatch.SlotCount)
                throw new ArgumentException(Invariant($"cp.Length ({cp.Length}) must be {GregoryPatch.SlotCount}"), nameof(cp));
            ref readonly GregoryPatchRecord r = ref Records()[patch];
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
                cp[k] = r[k].xyz;
        }

        /// <summary>_ControlPoints read as the GPU reads it, one record per patch (no copy).</summary>
        ReadOnlySpan<GregoryPatchRecord> Records() => MemoryMarshal.Cast<float, GregoryPatchRecord>(ControlPoints);

        void CheckPatch(int patch)
        {
            if ((uint)patch >= (uint)PatchCount())
                throw new ArgumentException(Invariant($"patch ({patch}) must lie in [0, {PatchCount() - 1}]"), nameof(patch));
        }

        static float Log2(float x) => (float)(Math.Log(x) / Math.Log(2.0));

        static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
