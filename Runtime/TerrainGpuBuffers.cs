using System;
using UnityEngine;

namespace GregoryTerrain
{
    // A renderer's GPU buffers, made, filled and released when it says (FrameResources decides).
    internal sealed class TerrainGpuBuffers
    {
        internal GraphicsBuffer ControlPoints { get; private set; }
        internal GraphicsBuffer Regions { get; private set; }
        internal GraphicsBuffer GridLines { get; private set; }
        internal GraphicsBuffer FallbackIndices { get; private set; }
        internal GraphicsBuffer NoiseCells { get; private set; }
        internal PatchGrid Grid { get; private set; }   // in the buffers, or null

        /// <summary>Null, the buffers made; else why the grid cannot be uploaded (nothing held).</summary>
        internal string Upload(PatchGrid g)
        {
            ReleaseGrid();   // never leave live buffers to the finalizer
            GregoryPatchRecord[] records;
            float[] regions, lines;
            // GpuLayout validates (bit-identical shared edges, float-representable lines) and packs.
            try { records = GpuLayout.PackPatchRecords(g); regions = GpuLayout.PackRegions(g); lines = GpuLayout.PackGridLines(g); }
            catch (ArgumentException e) { return e.Message; }
            // One 320-byte record a patch (StructuredBuffer<GregoryPatchRecord>); the regions a float array
            // of float4 elements: count = floats / 4, stride 16 (GpuLayout.Float4Stride).
            try
            {
                ControlPoints = new GraphicsBuffer(GraphicsBuffer.Target.Structured, records.Length, GpuLayout.PatchRecordStride);
                ControlPoints.SetData(records);
                Regions = new GraphicsBuffer(GraphicsBuffer.Target.Structured, regions.Length / GpuLayout.Float4Size, GpuLayout.Float4Stride);
                Regions.SetData(regions);
                GridLines = new GraphicsBuffer(GraphicsBuffer.Target.Structured, lines.Length, GpuLayout.GridLineStride);
                GridLines.SetData(lines);
            }
            // GraphicsBuffer refuses a size over SystemInfo.maxGraphicsBufferSize: told once, not thrown every frame.
            catch (ArgumentException e) { ReleaseGrid(); return e.Message; }
            Grid = g;
            return null;
        }

        /// <summary>Only the <paramref name="changed"/> patches (ascending).</summary>
        internal void UploadPatches(PatchGrid g, int[] changed)
        {
            var records = new GregoryPatchRecord[changed.Length];
            for (int k = 0; k < changed.Length; k++)
                records[k] = GpuLayout.PackPatchRecord(g.Patches[changed[k]]);
            for (int start = 0, end; start < changed.Length; start = end)   // one SetData per run of consecutive patches
            {
                for (end = start + 1; end < changed.Length && changed[end] == changed[end - 1] + 1; end++) { }
                ControlPoints.SetData(records, start, changed[start], end - start);
            }
            Grid = g;
        }

        /// <summary>The fallback's (F+1)^2-vertex grid as triangles.</summary>
        internal void BuildFallbackIndices(int f)
        {
            FallbackIndices?.Release();
            var indices = new int[6 * f * f];
            int k = 0, row = f + 1;
            for (int t = 0; t < f; t++)
            for (int s = 0; s < f; s++)
            {
                int v = t * row + s;
                indices[k++] = v; indices[k++] = v + row; indices[k++] = v + 1;
                indices[k++] = v + 1; indices[k++] = v + row; indices[k++] = v + row + 1;
            }
            FallbackIndices = new GraphicsBuffer(GraphicsBuffer.Target.Index, indices.Length, sizeof(int));
            FallbackIndices.SetData(indices);
        }

        /// <summary><c>_NoiseCells</c> (256 x 256 cells, 2 float4 each, 2 MiB), made on first use.</summary>
        internal GraphicsBuffer EnsureNoiseTable()
        {
            if (NoiseCells != null) return NoiseCells;
            float[] floats = GradientNoiseTable.Floats;   // shared with Core: read, never written
            NoiseCells = new GraphicsBuffer(GraphicsBuffer.Target.Structured,
                GradientNoiseTable.Size * GradientNoiseTable.Size * GradientNoiseTable.RowsPerCell, GpuLayout.Float4Stride);
            NoiseCells.SetData(floats);
            return NoiseCells;
        }

        internal void ReleaseNoiseTable()
        {
            NoiseCells?.Release(); NoiseCells = null;
        }

        internal void Release()
        {
            ReleaseGrid();
            FallbackIndices?.Release(); FallbackIndices = null;
            ReleaseNoiseTable();
        }

        void ReleaseGrid()
        {
            ControlPoints?.Release(); ControlPoints = null;
            Regions?.Release(); Regions = null;
            GridLines?.Release(); GridLines = null;
            Grid = null;
        }
    }
}
