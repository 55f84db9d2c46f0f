using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// A tile's record in the vertex cache's <c>_TileFactors</c> (internals.md, "Vertex cache"): what the
    /// draw reads, and the keys a renderer zeroes (with the whole buffer) to have every tile evaluated
    /// afresh. Written by <c>CacheTileFactors</c>, read by the hull stage and <c>CacheTileVertices</c>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/TileFactorRecord.cs.hlsl", Record = true)]
    internal struct TileFactorRecord
    {
        /// <summary>Bytes per record: the StructuredBuffer's stride (Marshal.SizeOf, checked by CacheRecordTests).</summary>
        public const int Stride = 4 * 16;

        [HlslComment("integer edge factors (u = 0, v = 0, u = 1, v = 1) the draw uses")]
        public Float4 edge;
        [HlslComment("(inside u, inside v, culled 1/0, evaluate 1/0: CacheTileVertices rewrites the slots)")]
        public Float4 inside;
        [HlslComment("the key (CellRecordKey) the slots hold; all 0: never written")]
        public Float4 slotsKey;
        [HlslComment("the key the cell's samples and factors (TileCellRecord) hold; all 0: never written")]
        public Float4 cellKey;
    }

    /// <summary>
    /// A tile's cell in the vertex cache's <c>_TileCells</c>, kept while <see cref="TileFactorRecord.cellKey"/>
    /// holds: its factors before rounding, what they were computed with, and its factor samples'
    /// object positions. Only <c>CacheTileFactors</c> reads and writes it.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/TileCellRecord.cs.hlsl", Record = true)]
    internal struct TileCellRecord
    {
        /// <summary>float4 of <see cref="input0"/>..: the camera's object-to-clip rows, then (screen size, max factor, target).</summary>
        public const int InputCount = 5;
        /// <summary>Bytes per record: the StructuredBuffer's stride.</summary>
        public const int Stride = (2 + InputCount + VertexCache.FactorSamplesPerTile) * 16;

        [HlslComment("the cell's float edge factors")]
        public Float4 edge;
        [HlslComment("(inside u, inside v, how they were decided: VertexCache.CellFactorsSampled.., 0)")]
        public Float4 inside;
        [HlslArray("inputs", InputCount), HlslComment("what the factors were computed with (FactorInput)")]
        public Float4 input0, input1, input2, input3, input4;
        [HlslArray("samples", VertexCache.FactorSamplesPerTile), HlslComment("factor sample positions (object space), w = 1 once written")]
        public Float4 sample0, sample1, sample2, sample3, sample4, sample5, sample6, sample7, sample8, sample9,
            sample10, sample11, sample12, sample13, sample14, sample15, sample16, sample17, sample18, sample19,
            sample20, sample21, sample22, sample23, sample24, sample25, sample26, sample27, sample28, sample29,
            sample30, sample31, sample32, sample33, sample34, sample35, sample36, sample37, sample38, sample39,
            sample40, sample41, sample42, sample43, sample44, sample45, sample46, sample47, sample48, sample49, sample50;
    }

    /// <summary>
    /// A draw patch's record in the levels' <c>_LodFactors</c> (internals.md, "Levels of detail"): written
    /// by the factor kernels, read by the levels' hull while <c>_LodLevels.y</c> is 1.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/LodFactorRecord.cs.hlsl", Record = true)]
    internal struct LodFactorRecord
    {
        /// <summary>Bytes per record: the StructuredBuffer's stride.</summary>
        public const int Stride = 4 * 16;

        [HlslComment("edge factors, seam rule applied, in no view culled")]
        public Float4 edge;
        [HlslComment("(inside u, inside v, 0, 0)")]
        public Float4 inside;
        [HlslArray("pieces", 2), HlslComment("the tile's seven pieces (TileFactorPiece): 0-3, then (4-6, 0)")]
        public Float4 piece0, piece1;
    }
}
