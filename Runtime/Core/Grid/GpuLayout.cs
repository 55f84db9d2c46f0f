using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// The only code that packs the GPU buffers of a patch grid (internals.md, "GPU layout"); the
    /// shaders' side is <c>Shaders/Grid/PatchGrid.hlsl</c>. Pure arrays: the caller uploads or writes them.
    /// <list type="table">
    /// <item><c>_ControlPoints</c>: StructuredBuffer&lt;float4&gt;, 20 per patch, patch p at float4
    /// index <c>20 p + slot</c>, (x, y, z, 1).</item>
    /// <item><c>_Regions</c>: StructuredBuffer&lt;float4&gt;, (a, b, e, f) of patch p at float4 index p.</item>
    /// <item><c>_GridLines</c>: StructuredBuffer&lt;float&gt;, xLines[0..n] then yLines[0..m].</item>
    /// <item><c>_GridSize</c>: float4 (n, m, 0, 0).</item>
    /// </list>
    /// float4, never float3: a float3 StructuredBuffer has a 12-byte stride in D3D and 16 in Vulkan.
    /// </summary>
    internal static class GpuLayout
    {
        /// <summary>Floats per float4 element.</summary>
        public const int Float4Size = 4;
        /// <summary>Bytes per float4 element: the stride of every StructuredBuffer&lt;float4&gt;.</summary>
        public const int Float4Stride = 16;

        /// <summary>Stride in bytes of a uint4 element (_VertexCache's records).</summary>
        public const int Uint4Stride = 16;
        /// <summary>float4 elements of _ControlPoints per patch.</summary>
        public const int ControlPointsPerPatch = GregoryPatch.SlotCount;
        /// <summary>Floats of _ControlPoints per patch (80).</summary>
        public const int ControlPointFloatsPerPatch = ControlPointsPerPatch * Float4Size;
        /// <summary>Floats of _Regions per patch (one float4).</summary>
        public const int RegionFloatsPerPatch = Float4Size;
        /// <summary>Stride of _GridLines in bytes (StructuredBuffer&lt;float&gt;).</summary>
        public const int GridLineStride = 4;
        /// <summary>The largest buffer allowed, in bytes (2 GiB: the limit of one buffer in most APIs and of a .NET array of float).</summary>
        public const long MaxBufferBytes = 1L << 31;
        /// <summary>The most patches: _GridSize carries n, m and patch indices as floats, exact up to 2^24.</summary>
        public const int MaxPatches = 1 << 24;

        /// <summary>Float index in <see cref="PackControlPoints"/>'s array of slot <paramref name="slot"/> of patch <paramref name="patch"/> (its x; y, z, w follow).</summary>
        public static long ControlPointOffset(int patch, int slot) => ((long)patch * ControlPointsPerPatch + slot) * Float4Size;

        /// <summary>Float index of patch p's region (a, b, e, f) in <see cref="PackRegions"/>'s array.</summary>
        public static long RegionOffset(int patch) => (long)patch * RegionFloatsPerPatch;

        /// <summary>Float index of yLines[0] in <see cref="PackGridLines"/>'s array (xLines come first).</summary>
        public static int YLinesOffset(int columns) => columns + 1;

        /// <summary>Bytes of _ControlPoints for a grid of <paramref name="patches"/> patches.</summary>
        public static long ControlPointBytes(long patches) => patches * ControlPointsPerPatch * Float4Stride;

        /// <summary>
        /// Throws ArgumentException unless the grid can be packed: <see cref="PatchGrid.Validate"/>
        /// holds every rule the buffers need (patch count, float range, float grid lines).
        /// </summary>
        public static void CheckPackable(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            grid.Validate();
        }

        /// <summary>Throws ArgumentException if an n x m grid would not fit the GPU buffers.</summary>
        public static void CheckSize(int columns, int rows)
        {
            PatchGrid.CheckShape(columns, rows);
            long patches = (long)columns * rows;
            if (patches > MaxPatches)
                throw new ArgumentException($"columns * rows = {columns} * {rows} = {patches} patches is more than {MaxPatches} (2^24, the most a float index can address).", nameof(columns));
            if (ControlPointBytes(patches) > MaxBufferBytes)
                throw new ArgumentException($"columns * rows = {columns} * {rows} = {patches} patches need {ControlPointBytes(patches)} bytes of _ControlPoints, more than the GPU buffer limit of {MaxBufferBytes} (2 GiB, {MaxBufferBytes / ControlPointBytes(1)} patches).", nameof(columns));
        }

        /// <summary>_ControlPoints: 20 float4 per patch, (x, y, z, 1), patch-major, slot order.</summary>
        public static float[] PackControlPoints(PatchGrid grid)
        {
            CheckPackable(grid);
            var data = new float[ControlPointBytes(grid.PatchCount) / sizeof(float)];
            for (int p = 0; p < grid.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    long o = ControlPointOffset(p, k);
                    Double3 c = grid.Patches[p][k];
                    data[o] = (float)c.x;
                    data[o + 1] = (float)c.y;
                    data[o + 2] = (float)c.z;
                    data[o + 3] = 1f;
                }
            return data;
        }

        /// <summary>_Regions: one float4 (a, b, e, f) per patch.</summary>
        public static float[] PackRegions(PatchGrid grid)
        {
            CheckPackable(grid);
            var data = new float[(long)grid.PatchCount * RegionFloatsPerPatch];
            for (int p = 0; p < grid.PatchCount; p++)
            {
                Region r = grid.RegionOf(p);
                long o = RegionOffset(p);
                data[o] = (float)r.a;
                data[o + 1] = (float)r.b;
                data[o + 2] = (float)r.e;
                data[o + 3] = (float)r.f;
            }
            return data;
        }

        /// <summary>_GridLines: xLines[0..n] then yLines[0..m], as floats.</summary>
        public static float[] PackGridLines(PatchGrid grid)
        {
            CheckPackable(grid);
            var data = new float[grid.Columns + 1 + grid.Rows + 1];
            for (int k = 0; k <= grid.Columns; k++) data[k] = (float)grid.XLines[k];
            for (int k = 0; k <= grid.Rows; k++) data[YLinesOffset(grid.Columns) + k] = (float)grid.YLines[k];
            return data;
        }

        /// <summary>_GridSize: (n, m, 0, 0).</summary>
        public static float[] GridSize(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            CheckSize(grid.Columns, grid.Rows);
            return new float[] { grid.Columns, grid.Rows, 0f, 0f };
        }
    }
}
