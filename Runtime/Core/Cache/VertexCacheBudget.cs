using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Sizes of the vertex cache's three buffers (GT_VERTEX_CACHE; internals.md, "Vertex cache"), for the
    /// Unity renderer and its inspector. Pure arithmetic from M, the factor limit L
    /// (<see cref="VertexCache.FactorLimit(Float4)"/>) and the snow flag; the slot layout itself is
    /// <see cref="VertexCache"/>'s, this class only counts.
    /// <list type="bullet">
    /// <item>Factor limit <c>L</c>: <c>ceil(_Tess.w)</c> when <c>_Tess.w &gt; 0</c> (uniform), else
    /// <c>ceil(_Tess.y)</c> (max factor), clamped to [1, 64]: the largest integer factor the
    /// <c>CacheTileFactors</c> kernel can give a tile.</item>
    /// <item>Slots per tile <c>S(L) = (L+1)^2 + 4 (L+1)</c>: the inside grid of the largest inside
    /// factors, then each of the four edges' <c>L+1</c> points.</item>
    /// <item>uint4 per slot <c>R</c>: 1, or 2 with GT_SNOW.</item>
    /// <item><c>_TileFactors</c>: <c>M^2</c> <see cref="TileFactorRecord"/> (64 M^2 bytes); <c>_TileCells</c>:
    /// <c>M^2</c> <see cref="TileCellRecord"/> (928 M^2 bytes); <c>_VertexCache</c>: <c>M^2 S(L) R</c> uint4 (16 bytes each).</item>
    /// </list>
    /// </summary>
    internal static class VertexCacheBudget
    {
        /// <summary>Bytes of <c>_TileFactors</c>: 64 M^2.</summary>
        public static long TileFactorsBytes(int tiles) => Tiles(tiles) * TileFactorRecord.Stride;

        /// <summary>Bytes of <c>_TileCells</c>: 928 M^2.</summary>
        public static long TileCellsBytes(int tiles) => Tiles(tiles) * TileCellRecord.Stride;

        /// <summary>uint4 elements of <c>_VertexCache</c>: M^2 S(L) R.</summary>
        public static long VertexCacheUint4s(int tiles, int factorLimit, bool snow) =>
            Tiles(tiles) * VertexCache.SlotsPerTile(factorLimit) * VertexCache.Uint4sPerRecord(snow);

        /// <summary>Bytes of <c>_VertexCache</c>: 16 M^2 S(L) R.</summary>
        public static long VertexCacheBytes(int tiles, int factorLimit, bool snow) =>
            VertexCacheUint4s(tiles, factorLimit, snow) * GpuLayout.Uint4Stride;

        /// <summary>GPU memory of the three buffers together.</summary>
        public static long TotalBytes(int tiles, int factorLimit, bool snow) =>
            TileFactorsBytes(tiles) + TileCellsBytes(tiles) + VertexCacheBytes(tiles, factorLimit, snow);

        /// <summary>
        /// Throws ArgumentException, naming the settings and the bytes, when _VertexCache or _TileCells (_TileFactors is smaller) is larger
        /// than <paramref name="maxBufferBytes"/> (the device's largest buffer; Unity:
        /// <c>SystemInfo.maxGraphicsBufferSize</c>) or than <see cref="GpuLayout.MaxBufferBytes"/>
        /// (2 GiB, the most a GraphicsBuffer's int count of float4 safely addresses everywhere).
        /// Nothing is allocated here: call it before touching the old buffers.
        /// </summary>
        public static void CheckFits(int tiles, int factorLimit, bool snow, long maxBufferBytes)
        {
            if (maxBufferBytes <= 0)
                throw new ArgumentException(FormattableString.Invariant($"maxBufferBytes ({maxBufferBytes}) must be > 0"), nameof(maxBufferBytes));
            long limit = Math.Min(maxBufferBytes, GpuLayout.MaxBufferBytes);
            long cache = VertexCacheBytes(tiles, factorLimit, snow);
            if (cache > limit)
                throw new ArgumentException(FormattableString.Invariant(
                    $"the vertex cache for tiles = {tiles}, factor limit {factorLimit}{(snow ? ", snow" : "")} needs {cache} bytes (_VertexCache = M^2 ((L+1)^2 + 4 (L+1)) x {VertexCache.Uint4sPerRecord(snow)} uint4), more than the largest buffer, {limit} bytes; lower tiles or the max/uniform factor, or evaluate in the domain stage"),
                    "tiles");
            long cells = TileCellsBytes(tiles);
            if (cells > limit)
                throw new ArgumentException(FormattableString.Invariant(
                    $"the tile cells for tiles = {tiles} need {cells} bytes (_TileCells = 928 M^2), more than the largest buffer, {limit} bytes"), "tiles");
        }

        // M^2, the records of each per-tile buffer.
        static long Tiles(int tiles)
        {
            if (tiles < 1 || tiles > 1024)
                throw new ArgumentException(FormattableString.Invariant($"tiles ({tiles}) must lie in [1, 1024]"), nameof(tiles));
            return (long)tiles * tiles;
        }
    }
}
