using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// A tile's record in the vertex cache's <c>_TileFactors</c> (internals.md, "Vertex cache"): what the
    /// draw reads, and the keys zeroed to have the tile evaluated afresh. Stride: Marshal.SizeOf.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/TileFactorRecord.cs.hlsl", Record = true)]
    internal struct TileFactorRecord
    {
        public const int Stride = 4 * 16;

        [HlslComment("integer factors the draw uses")]
        public Float4 edge;
        [HlslComment("(inside u, v, culled 1/0, evaluate 1/0)")]
        public Float4 inside;
        [HlslComment("CellRecordKey the slots hold; 0: none")]
        public Float4 slotsKey;
        [HlslComment("CellRecordKey the TileCellRecord holds; 0: none")]
        public Float4 cellKey;
    }

    /// <summary>A tile's cell in <c>_TileCells</c>, kept while its key holds; the cache kernels' alone.</summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/TileCellRecord.cs.hlsl", Record = true)]
    internal struct TileCellRecord
    {
        public const int InputCount = 5;
        public const int Stride = (2 + InputCount + VertexCache.FactorSamplesPerTile) * 16;

        [HlslComment("float factors before rounding")]
        public Float4 edge;
        [HlslComment("(inside u, v, VertexCache.CellFactors*, 0)")]
        public Float4 inside;
        [HlslArray("inputs", InputCount), HlslComment("FactorInput 0-4 they were computed with")]
        public Float4 input0, input1, input2, input3, input4;
        [HlslArray("samples", VertexCache.FactorSamplesPerTile), HlslComment("object positions, w = 1 once written")]
        public Float4 sample0, sample1, sample2, sample3, sample4, sample5, sample6, sample7, sample8, sample9,
            sample10, sample11, sample12, sample13, sample14, sample15, sample16, sample17, sample18, sample19,
            sample20, sample21, sample22, sample23, sample24, sample25, sample26, sample27, sample28, sample29,
            sample30, sample31, sample32, sample33, sample34, sample35, sample36, sample37, sample38, sample39,
            sample40, sample41, sample42, sample43, sample44, sample45, sample46, sample47, sample48, sample49, sample50;
    }

    /// <summary>A draw patch's record in the levels' <c>_LodFactors</c> (internals.md, "Levels of detail").</summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Cache/LodFactorRecord.cs.hlsl", Record = true)]
    internal struct LodFactorRecord
    {
        public const int Stride = 4 * 16;

        [HlslComment("factors, seam rule applied, culled in no view")]
        public Float4 edge;
        [HlslComment("xy factors; z first cache record, -1 none; w (patch 0) records needed")]
        public Float4 inside;
        [HlslArray("pieces", 2), HlslComment("TileFactorPiece 0-3, then 4-6, then camera culls 1/0")]
        public Float4 piece0, piece1;
    }
}
