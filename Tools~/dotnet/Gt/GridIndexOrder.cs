using System;
using System.Collections.Generic;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// Index orders of the fair static mesh's grid (gt bench; harness --grid-indices): the same
    /// 2 F^2 triangles of an (F+1) x (F+1) vertex grid, same winding, in an order the GPU's
    /// post-transform cache reuses well. Row by row (the harness's own order) re-runs the vertex
    /// stage about twice per vertex on an H200; what a mesh optimiser would emit is Forsyth's
    /// linear-speed vertex cache optimisation, implemented here from its description (T. Forsyth,
    /// "Linear-Speed Vertex Cache Optimisation", 2006).
    /// </summary>
    static class GridIndexOrder
    {
        public static string FileName(string method, int f) => $"{method}_f{f}.u32";

        /// <summary>The harness's own order, the renderer's fallback index buffer: cell by cell, row by row,
        /// triangles (v, v + row, v + 1), (v + 1, v + row, v + row + 1), clockwise from above.</summary>
        public static uint[] RowMajor(int f)
        {
            var idx = new uint[6 * f * f];
            int k = 0;
            for (int j = 0; j < f; j++)
                for (int i = 0; i < f; i++)
                    k = Cell(idx, k, f, i, j);
            return idx;
        }

        /// <summary>Columns of <paramref name="width"/> cells, each walked row by row (the cells' triangles as in <see cref="RowMajor"/>).</summary>
        public static uint[] Strips(int f, int width)
        {
            var idx = new uint[6 * f * f];
            int k = 0;
            for (int s = 0; s < f; s += width)
                for (int j = 0; j < f; j++)
                    for (int i = s; i < Math.Min(s + width, f); i++)
                        k = Cell(idx, k, f, i, j);
            return idx;
        }

        static int Cell(uint[] idx, int k, int f, int i, int j)
        {
            uint row = (uint)(f + 1), v = (uint)j * row + (uint)i;
            idx[k] = v; idx[k + 1] = v + row; idx[k + 2] = v + 1; idx[k + 3] = v + 1; idx[k + 4] = v + row; idx[k + 5] = v + row + 1;
            return k + 6;
        }

        // Forsyth's scoring: a vertex in the modelled LRU cache scores by its position (the last
        // triangle's three a fixed 0.75, then falling as (1 - p')^1.5), plus 2 / sqrt(triangles it
        // still has), so vertices with few triangles left are finished first.
        const int CacheSize = 32;
        const double LastTriangleScore = 0.75, DecayPower = 1.5, ValenceScale = 2.0, ValencePower = 0.5;

        static double VertexScore(int position, int remaining)
        {
            if (remaining == 0) return -1.0;
            double s = 0;
            if (position >= 0)
                s = position < 3 ? LastTriangleScore : Math.Pow(1.0 - (position - 3) / (double)(CacheSize - 3), DecayPower);
            return s + ValenceScale * Math.Pow(remaining, -ValencePower);
        }

        /// <summary>
        /// The triangles of <paramref name="indices"/> reordered by Forsyth's algorithm (LRU cache of
        /// 32): each step emits the best-scoring triangle among those of the cached vertices (a scan of
        /// the rest only when none is left), then rescores the cache. Triangles keep their winding.
        /// </summary>
        public static uint[] Forsyth(uint[] indices, int vertexCount)
        {
            int triangles = indices.Length / 3;
            var remaining = new int[vertexCount];
            foreach (uint v in indices) remaining[v]++;
            var offset = new int[vertexCount + 1];
            for (int v = 0; v < vertexCount; v++) offset[v + 1] = offset[v] + remaining[v];
            var trisOf = new int[indices.Length];
            var fill = (int[])offset.Clone();
            for (int t = 0; t < triangles; t++)
                for (int c = 0; c < 3; c++) trisOf[fill[indices[3 * t + c]]++] = t;
            var position = new int[vertexCount];
            var score = new double[vertexCount];
            for (int v = 0; v < vertexCount; v++) { position[v] = -1; score[v] = VertexScore(-1, remaining[v]); }
            var emitted = new bool[triangles];
            var triScore = new double[triangles];
            for (int t = 0; t < triangles; t++) triScore[t] = score[indices[3 * t]] + score[indices[3 * t + 1]] + score[indices[3 * t + 2]];

            var order = new uint[indices.Length];
            var cache = new List<int>(CacheSize + 3);
            int best = -1, scan = 0;
            for (int n = 0; n < triangles; n++)
            {
                if (best < 0)
                {
                    double bestScore = double.NegativeInfinity;
                    while (scan < triangles && emitted[scan]) scan++;   // the first left: all before it are emitted
                    for (int t = scan; t < triangles; t++)
                        if (!emitted[t] && triScore[t] > bestScore) { bestScore = triScore[t]; best = t; }
                }
                int tri = best;
                emitted[tri] = true;
                for (int c = 0; c < 3; c++)
                {
                    uint v = indices[3 * tri + c];
                    order[3 * n + c] = v;
                    remaining[v]--;
                    // Remove tri from v's live list (swap it past the live end).
                    int lo = offset[v], live = lo + remaining[v];
                    for (int k = lo; k <= live; k++)
                        if (trisOf[k] == tri) { trisOf[k] = trisOf[live]; trisOf[live] = tri; break; }
                }
                // New cache: the triangle's vertices first, then the old cache without them.
                var next = new List<int>(CacheSize + 3);
                for (int c = 0; c < 3; c++) next.Add((int)indices[3 * tri + c]);
                foreach (int v in cache) if (!next.Contains(v)) next.Add(v);
                for (int k = 0; k < next.Count; k++)
                {
                    int v = next[k];
                    position[v] = k < CacheSize ? k : -1;
                    score[v] = VertexScore(position[v], remaining[v]);
                }
                best = -1;
                double top = double.NegativeInfinity;
                foreach (int v in next)
                    for (int k = offset[v]; k < offset[v] + remaining[v]; k++)
                    {
                        int t = trisOf[k];
                        double s = score[indices[3 * t]] + score[indices[3 * t + 1]] + score[indices[3 * t + 2]];
                        triScore[t] = s;
                        if (s > top) { top = s; best = t; }
                    }
                if (next.Count > CacheSize) next.RemoveRange(CacheSize, next.Count - CacheSize);
                cache = next;
            }
            return order;
        }

        /// <summary>Vertex-stage runs per triangle of <paramref name="indices"/> through a FIFO cache of <paramref name="size"/> (a model, not the GPU).</summary>
        public static double FifoAcmr(uint[] indices, int size)
        {
            var fifo = new Queue<uint>();
            var held = new HashSet<uint>();
            long misses = 0;
            foreach (uint v in indices)
            {
                if (held.Contains(v)) continue;
                misses++;
                fifo.Enqueue(v); held.Add(v);
                if (fifo.Count > size) held.Remove(fifo.Dequeue());
            }
            return misses / (indices.Length / 3.0);
        }
    }
}
