using System;
using System.Globalization;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// The only code that packs the GPU buffers of a patch grid (internals.md, "GPU layout"); the
    /// shaders' side is <c>Shaders/Grid/PatchGrid.hlsl</c>. Pure arrays: the caller uploads or writes them.
    /// <list type="table">
    /// <item><c>_ControlPoints</c>: StructuredBuffer&lt;GregoryPatchRecord&gt;, one 320-byte record per
    /// patch, <c>points[slot]</c> (<see cref="GregoryPatchRecord"/>): xyz = <c>P - R_p</c>, the point
    /// relative to the patch's reference point <c>R_p</c>; w of slots 0, 1, 2 = <c>R_p</c>.x, .y, .z,
    /// w of the other slots 0. As floats: patch p's slot k at float index <c>80 p + 4 k</c>.</item>
    /// <item><c>_Regions</c>: StructuredBuffer&lt;float4&gt;, (a, b, e, f) of patch p at float4 index p (hi parts).</item>
    /// <item><c>_GridLines</c>: StructuredBuffer&lt;float&gt;, hi parts xLines[0..n], yLines[0..m], then
    /// the lo parts in the same order (line = hi + lo to ~1e-16).</item>
    /// <item><c>_GridSize</c>: float4 (n, m, 0, 0).</item>
    /// </list>
    /// float4, never float3: a float3 StructuredBuffer has a 12-byte stride in D3D and 16 in Vulkan.
    /// <para>Why relative points: internals.md, "GPU layout", "Patch records (precision)". The
    /// reference rides in the w components, which the evaluation loads anyway: no byte more per patch.</para>
    /// </summary>
    internal static class GpuLayout
    {
        /// <summary>Floats per float4 element.</summary>
        public const int Float4Size = 4;
        /// <summary>Bytes per float4 element: the stride of every StructuredBuffer&lt;float4&gt;.</summary>
        public const int Float4Stride = 16;

        /// <summary>Stride in bytes of a uint4 element (_VertexCache's records).</summary>
        public const int Uint4Stride = 16;
        /// <summary>float4 points of _ControlPoints per patch (one <see cref="GregoryPatchRecord"/>).</summary>
        public const int ControlPointsPerPatch = GregoryPatchRecord.PointCount;
        /// <summary>Bytes per patch record: the stride of _ControlPoints (StructuredBuffer&lt;GregoryPatchRecord&gt;).</summary>
        public const int PatchRecordStride = GregoryPatchRecord.Stride;
        /// <summary>Floats of _ControlPoints per patch (80).</summary>
        public const int ControlPointFloatsPerPatch = ControlPointsPerPatch * Float4Size;
        /// <summary>Floats of _Regions per patch (one float4).</summary>
        public const int RegionFloatsPerPatch = Float4Size;
        /// <summary>The slot whose point, rounded to float, is the patch's reference point R_p (the w of slots 0..2 hold it).</summary>
        public const int ReferenceSlot = 0;
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

        /// <summary>Float index of xLines[0]'s lo part in <see cref="PackGridLines"/>'s array (after all hi parts).</summary>
        public static int GridLinesLoOffset(int columns, int rows) => columns + 1 + rows + 1;

        /// <summary>The reference point R_p of a patch: its slot-0 point rounded to float (exact on the GPU).</summary>
        public static Float3 PatchReference(GregoryPatch patch)
        {
            if (patch == null) throw new ArgumentNullException(nameof(patch));
            return (Float3)patch[ReferenceSlot];
        }

        /// <summary>Bytes of _ControlPoints for a grid of <paramref name="patches"/> patches.</summary>
        public static long ControlPointBytes(long patches) => patches * PatchRecordStride;

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

        /// <summary>
        /// _ControlPoints: one record per patch, patch-major, points in slot order; xyz = <c>P_k - R_p</c>
        /// (formed in double, then rounded), w = R_p.x, R_p.y, R_p.z in slots 0, 1, 2 and 0 elsewhere.
        /// What the renderer uploads (stride <see cref="PatchRecordStride"/>).
        /// </summary>
        public static GregoryPatchRecord[] PackPatchRecords(PatchGrid grid)
        {
            CheckPackable(grid);
            var data = new GregoryPatchRecord[grid.PatchCount];
            for (int p = 0; p < grid.PatchCount; p++) data[p] = PackPatchRecord(grid.Patches[p]);
            return data;
        }

        /// <summary>One patch's record of <see cref="PackPatchRecords"/> (a patch of a validated grid: an edit uploads only these).</summary>
        public static GregoryPatchRecord PackPatchRecord(GregoryPatch patch)
        {
            Float3 r = PatchReference(patch);
            var record = new GregoryPatchRecord();
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
            {
                Double3 c = patch[k];
                record[k] = new Float4((float)(c.x - r.x), (float)(c.y - r.y), (float)(c.z - r.z),
                    k == 0 ? r.x : k == 1 ? r.y : k == 2 ? r.z : 0f);
            }
            return record;
        }

        /// <summary>
        /// The bytes of <see cref="PackPatchRecords"/> as floats (80 per patch, <see cref="ControlPointOffset"/>):
        /// what Core's <see cref="TerrainInputs"/> and the rig's buffer files hold.
        /// </summary>
        public static float[] PackControlPoints(PatchGrid grid) =>
            MemoryMarshal.Cast<GregoryPatchRecord, float>(PackPatchRecords(grid)).ToArray();

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

        /// <summary>
        /// _GridLines: the hi parts xLines[0..n], yLines[0..m] (the float lines FindPatch searches), then
        /// the lo parts in the same order, <c>lo = (float)(line - hi)</c>: a line such as 0.13 is off by
        /// 4.8e-9 as one float (9% of a range 1e-7 wide) and by ~1e-16 as the pair.
        /// </summary>
        public static float[] PackGridLines(PatchGrid grid)
        {
            CheckPackable(grid);
            int lo = GridLinesLoOffset(grid.Columns, grid.Rows);
            var data = new float[2 * lo];
            for (int k = 0; k <= grid.Columns; k++) SplitLine(grid.XLines[k], out data[k], out data[lo + k]);
            for (int k = 0; k <= grid.Rows; k++)
                SplitLine(grid.YLines[k], out data[YLinesOffset(grid.Columns) + k], out data[lo + YLinesOffset(grid.Columns) + k]);
            return data;
        }

        static void SplitLine(double line, out float hi, out float lo)
        {
            hi = (float)line;
            lo = (float)(line - hi);
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
