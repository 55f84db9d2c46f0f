using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The terrain as the snow simulation sees it: the <see cref="SnowField"/> (detail normal and
    /// height per cell) evaluated from the terrain's own inputs by the terrain's own vertex path.
    /// Mirrors <c>Shaders/Snow/SnowField.compute</c> (kernel <c>SnowFieldKernel</c>).
    /// <para>
    /// With the range the whole unit square, no origin and <c>M = R</c> tiles, tile <c>(i, j)</c> at
    /// tess <c>(0.5, 0.5)</c> is exactly the centre of cell (i, j) (R is a power of two), so the field is
    /// <see cref="TerrainVertex.Evaluate"/> of tile <c>j R + i</c> under <see cref="ParamsFor"/>: no
    /// second copy of the path to drift. Octaves shorter than two cells are left out (<c>verticesAcross = R</c>).
    /// </para>
    /// </summary>
    internal static class SnowFieldTerrain
    {
        /// <summary>The tess coordinate of a cell centre inside its one-cell tile.</summary>
        public static readonly Float2 CellCentreTess = new Float2(0.5f, 0.5f);

        /// <summary>
        /// The <c>TerrainParams</c> the field kernel runs with: <paramref name="terrain"/>'s grid, noise
        /// and colours, the range (0, 0, 1, 1) with no origin, <c>_Tess = (R, maxFactor, pixels, 1)</c>,
        /// the noise budget <c>verticesAcross = R</c> and the cells on that range (no tile lattice).
        /// </summary>
        public static TerrainParams ParamsFor(TerrainParams terrain, int resolution)
        {
            CheckResolution(resolution);
            TerrainParams p = terrain;
            p.range = new Float4(0f, 0f, 1f, 1f);
            p.rangeOrigin = new Float4(0f, 0f, 0f, 0f);
            p.tess = new Float4(resolution, terrain.tess.y, terrain.tess.z, 1f);
            p.noiseOctaves = new Float4(terrain.noiseOctaves.x, resolution, 0f, 0f);
            p.tileLattice = new Float4(0f, 0f, 0f, 0f);
            p.originSurface = default;   // the levels' origin, per camera: the field has none (a change would re-run it)
            return p;
        }

        /// <summary>
        /// One cell, <c>(detail normal.xyz, height)</c>, from inputs whose params are
        /// <see cref="ParamsFor"/>'s: HLSL <c>SnowFieldKernel</c> at thread (i, j).
        /// </summary>
        public static Float4 EvaluateCell(TerrainInputs fieldInputs, int i, int j, TerrainKeywords keywords)
        {
            if (fieldInputs == null) throw new ArgumentNullException(nameof(fieldInputs));
            int r = fieldInputs.TileCountInt();
            if ((uint)i >= (uint)r || (uint)j >= (uint)r)
                throw new ArgumentException(FormattableString.Invariant($"cell ({i}, {j}) is outside the {r} x {r} field"), nameof(i));
            TerrainVertexOutput v = TerrainVertex.Evaluate(fieldInputs, j * r + i, CellCentreTess, keywords);
            return new Float4(v.normal.x, v.normal.y, v.normal.z, v.position.z);
        }

        /// <summary>
        /// Evaluates every cell of <paramref name="field"/> from the terrain's inputs (any params: they
        /// are replaced by <see cref="ParamsFor"/>) and marks it changed. Only
        /// <see cref="TerrainKeywords.Noise"/> matters; snow and paper mode are refused (the field is the
        /// bare terrain, in tile mode).
        /// </summary>
        public static void Evaluate(TerrainInputs terrain, SnowField field, TerrainKeywords keywords)
        {
            if (terrain == null) throw new ArgumentNullException(nameof(terrain));
            if (field == null) throw new ArgumentNullException(nameof(field));
            if ((keywords & (TerrainKeywords.Snow | TerrainKeywords.PaperMode)) != 0)
                throw new ArgumentException($"keywords ({keywords}) must not include Snow or PaperMode: the field is the bare terrain", nameof(keywords));
            int r = field.Resolution;
            TerrainInputs inputs = terrain.WithParams(ParamsFor(terrain.Params, r)).WithSnow(null);
            float[] data = field.Data;
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                {
                    Float4 c = EvaluateCell(inputs, i, j, keywords);
                    int k = 4 * (j * r + i);
                    data[k] = c.x; data[k + 1] = c.y; data[k + 2] = c.z; data[k + 3] = c.w;
                }
            field.MarkChanged();
        }

        static void CheckResolution(int resolution)
        {
            if (resolution < SnowSettings.MinResolution || resolution > SnowSettings.MaxResolution || (resolution & (resolution - 1)) != 0)
                throw new ArgumentException(FormattableString.Invariant($"resolution ({resolution}) must be a power of two from 64 to 4096"), nameof(resolution));
        }
    }
}
