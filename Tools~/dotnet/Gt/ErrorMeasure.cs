using System;
using System.Collections.Generic;
using System.Threading;
using System.Threading.Tasks;

namespace GregoryTerrain.Rig
{
    /// <summary>The factors the hull stage gave one drawn patch (tile, or Gregory patch in paper mode).</summary>
    struct PatchFactors
    {
        /// <summary>edge[0]: u = 0, edge[1]: v = 0, edge[2]: u = 1, edge[3]: v = 1.</summary>
        public double e0, e1, e2, e3;
        /// <summary>inside[0] along u, inside[1] along v.</summary>
        public double i0, i1;
        public bool culled;

        public static PatchFactors Uniform(double f) => new PatchFactors { e0 = f, e1 = f, e2 = f, e3 = f, i0 = f, i1 = f };

        /// <summary>Reads GT_FACTOR_READBACK's 2 float4 per patch (Tools~/rig/README.md, "Rig-only readback").</summary>
        public static PatchFactors[] FromReadback(float[] r, int patches)
        {
            if (r.Length < 8 * patches)
                throw new FormatException($"factor readback holds {r.Length} floats, {8 * patches} expected for {patches} patches");
            var f = new PatchFactors[patches];
            for (int p = 0; p < patches; p++)
            {
                int o = 8 * p;
                for (int k = 0; k < 8; k++)
                    if (float.IsNaN(r[o + k]))
                        throw new FormatException($"factor readback: patch {p} float {k} is NaN (never written)");
                f[p] = new PatchFactors { e0 = r[o], e1 = r[o + 1], e2 = r[o + 2], e3 = r[o + 3], i0 = r[o + 4], i1 = r[o + 5], culled = r[o + 6] != 0f };
            }
            return f;
        }

        /// <summary>
        /// The vertex cache's integer factors (kernel CacheTileFactors) of the factors hull_const would
        /// give (Core's mirror), by Core's VertexCache.IntegerFactors (HLSL VertexCacheIntegerFactors),
        /// in float as the kernel: each of the six ceil(clamp(F, 1, 64)); a culled tile all 0; unless
        /// all six are 1, each inside factor at least 2 (the tessellator treats an inside 1 as 2
        /// whenever anything else is subdivided).
        /// </summary>
        public PatchFactors CacheIntegers()
        {
            if (culled) return new PatchFactors { culled = true };
            var f = VertexCache.IntegerFactors(new TileFactorSet(new Float4((float)e0, (float)e1, (float)e2, (float)e3), new Float2((float)i0, (float)i1)));
            return new PatchFactors { e0 = f.edge.x, e1 = f.edge.y, e2 = f.edge.z, e3 = f.edge.w, i0 = f.inside.x, i1 = f.inside.y };
        }

        /// <summary>
        /// Reads a dump of the vertex cache's <c>_TileFactors</c> (binding 7, harness --dump-storage):
        /// a TileFactorRecord per tile, (edge0..3), (inside0, inside1, culled 1/0, evaluated 1/0), keys, and checks the
        /// contract the domain stage's slot grid relies on: a culled tile is all 0 and not evaluated; a
        /// drawn one has six integers in
        /// [1, 64] and, unless all six are 1, inside factors of at least 2. A tile the kernel never
        /// wrote (the buffer starts zero-filled) reads as drawn with factor 0 and is refused.
        /// </summary>
        /// <summary>Floats of a tile's record in the dump (TileFactorRecord: edge, inside, keys).</summary>
        public const int TileRecordFloats = TileFactorRecord.Stride / 4;

        /// <summary>The layout FromTileFactors reads (a TileFactorRecord a tile, keys 0), e.g. for Core's prediction.</summary>
        public static float[] ToTileFactors(PatchFactors[] f)
        {
            var r = new float[TileRecordFloats * f.Length];
            for (int p = 0; p < f.Length; p++)
            {
                if (f[p].culled) { r[TileRecordFloats * p + 6] = 1f; continue; }
                var v = new[] { f[p].e0, f[p].e1, f[p].e2, f[p].e3, f[p].i0, f[p].i1 };
                for (int k = 0; k < 6; k++) r[TileRecordFloats * p + k] = (float)v[k];
            }
            return r;
        }

        public static PatchFactors[] FromTileFactors(float[] r, int tiles)
        {
            if (r.Length < TileRecordFloats * tiles)
                throw new FormatException($"_TileFactors dump holds {r.Length} floats, {TileRecordFloats * tiles} expected for {tiles} tiles");
            var f = new PatchFactors[tiles];
            for (int p = 0; p < tiles; p++)
            {
                int o = TileRecordFloats * p;
                string Where() => $"_TileFactors tile {p} ({string.Join(", ", Array.ConvertAll(r[o..(o + 8)], x => x.ToString("R", System.Globalization.CultureInfo.InvariantCulture)))})";
                if (r[o + 7] != 0f && r[o + 7] != 1f) throw new FormatException($"{Where()}: the evaluated flag is neither 0 nor 1");
                if (r[o + 6] == 1f)
                {
                    for (int k = 0; k < 6; k++)
                        if (r[o + k] != 0f) throw new FormatException($"{Where()}: culled, but its factors are not all 0");
                    if (r[o + 7] != 0f) throw new FormatException($"{Where()}: culled, but marked evaluated");
                    f[p] = new PatchFactors { culled = true };
                    continue;
                }
                if (r[o + 6] != 0f) throw new FormatException($"{Where()}: culled flag is neither 0 nor 1");
                for (int k = 0; k < 6; k++)
                {
                    float x = r[o + k];
                    if (!(x >= 1f && x <= 64f) || x != MathF.Floor(x))
                        throw new FormatException($"{Where()}: factor {k} is not an integer in [1, 64]" + (x == 0f ? " (never written?)" : ""));
                }
                var t = new PatchFactors { e0 = r[o], e1 = r[o + 1], e2 = r[o + 2], e3 = r[o + 3], i0 = r[o + 4], i1 = r[o + 5] };
                bool allOne = t.e0 == 1 && t.e1 == 1 && t.e2 == 1 && t.e3 == 1 && t.i0 == 1 && t.i1 == 1;
                if (!allOne && (t.i0 < 2 || t.i1 < 2))
                    throw new FormatException($"{Where()}: an inside factor is 1 while another factor is above 1 (the cache makes it 2)");
                f[p] = t;
            }
            return f;
        }
    }

    /// <summary>The largest and RMS distance between the drawn triangles and the exact surface.</summary>
    sealed class ErrorResult
    {
        public double MaxWorld, RmsWorld, MaxPixels, RmsPixels;
        /// <summary>
        /// With a drawn surface apart from the exact one (<see cref="ErrorMeasure.Measure(Func{int, double, double, double[]}, Func{int, double, double, double[]}, PatchFactors[], RigCamera, bool, int)"/>):
        /// the on-screen distance between where the drawn triangle shows a sample (its vertices
        /// projected by the float object-to-clip matrix, as the GPU does, the clip coordinates
        /// interpolated) and where the exact point projects in double. 0 otherwise.
        /// </summary>
        public double MaxScreenPixels, RmsScreenPixels;
        public long Samples, Triangles;
        public int CulledPatches;

        public override string ToString() => FormattableString.Invariant(
            $"error max_world {MaxWorld:G4} rms_world {RmsWorld:G4} max_px {MaxPixels:G4} rms_px {RmsPixels:G4} samples {Samples} triangles_model {Triangles} culled {CulledPatches}");
    }

    /// <summary>
    /// The error of a tessellation against the exact surface, on the CPU. Each drawn patch is cut
    /// into the cells its factors imply (<see cref="TessellationCells"/>): the inside factors give
    /// the grid of cells, the edge factors the segments along the patch's border. At each cell edge's
    /// midpoint, each border segment's midpoint and each cell's centre (on both diagonals: which one the
    /// tessellator splits along is its choice), the linear interpolation of the evaluated vertices is
    /// compared with the exact surface at the same parameter: a distance in object (terrain) units,
    /// and in pixels: that distance times the largest pixels per unit at the exact point (the
    /// knob's definition, TessellationPolicy.PixelsPerUnit). Only samples inside the view count.
    /// The transition ring between a coarser border and the inside grid is not modelled; the
    /// border's own segments are.
    /// </summary>
    static class ErrorMeasure
    {
        static readonly bool Debug = Environment.GetEnvironmentVariable("GT_ERROR_DEBUG") == "1";

        /// <summary>
        /// surface(patch, s, t): the exact object-space point at tess coordinate (s, t) of a drawn patch.
        /// camera: for the pixel scale and the visibility test (null: every sample counts, pixels 0).
        /// maxCellsPerPatch: larger grids are sampled with a stride (row and column) to bound the work.
        /// </summary>
        public static ErrorResult Measure(Func<int, double, double, double[]> surface, PatchFactors[] factors,
                                          RigCamera camera, bool fractionalOdd = true, int maxCellsPerPatch = 1 << 20) =>
            Measure(surface, surface, factors, camera, fractionalOdd, maxCellsPerPatch);

        /// <summary>
        /// The same with the vertices where the GPU puts them (<paramref name="drawn"/>: e.g. Core's float
        /// mirror of the vertex stage, fewer noise octaves far away) and the surface they stand for
        /// (<paramref name="exact"/>: the double full-detail surface). Then the vertices themselves are
        /// samples too, and <see cref="ErrorResult.MaxScreenPixels"/> is filled (needs a camera).
        /// </summary>
        public static ErrorResult Measure(Func<int, double, double, double[]> drawn, Func<int, double, double, double[]> exact,
                                          PatchFactors[] factors, RigCamera camera, bool fractionalOdd = true, int maxCellsPerPatch = 1 << 20)
        {
            if (drawn == null) throw new ArgumentNullException(nameof(drawn));
            if (exact == null) throw new ArgumentNullException(nameof(exact));
            if (factors == null || factors.Length == 0) throw new ArgumentException("factors must name at least one patch", nameof(factors));
            var partial = new ErrorResult[factors.Length];
            Parallel.For(0, factors.Length, p => partial[p] = MeasurePatch(drawn, exact, p, factors[p], camera, fractionalOdd, maxCellsPerPatch));
            var r = new ErrorResult();
            double sw = 0, sp = 0, ss = 0;
            foreach (var q in partial)
            {
                r.MaxWorld = Math.Max(r.MaxWorld, q.MaxWorld);
                r.MaxPixels = Math.Max(r.MaxPixels, q.MaxPixels);
                r.MaxScreenPixels = Math.Max(r.MaxScreenPixels, q.MaxScreenPixels);
                sw += q.RmsWorld; sp += q.RmsPixels; ss += q.RmsScreenPixels;   // sums of squares here
                r.Samples += q.Samples;
                r.Triangles += q.Triangles;
                r.CulledPatches += q.CulledPatches;
            }
            r.RmsWorld = r.Samples > 0 ? Math.Sqrt(sw / r.Samples) : 0;
            r.RmsPixels = r.Samples > 0 ? Math.Sqrt(sp / r.Samples) : 0;
            r.RmsScreenPixels = r.Samples > 0 ? Math.Sqrt(ss / r.Samples) : 0;
            return r;
        }

        // Per patch; RmsWorld/RmsPixels hold sums of squares until Measure divides.
        static ErrorResult MeasurePatch(Func<int, double, double, double[]> surface, Func<int, double, double, double[]> exact, int patch,
                                        PatchFactors f, RigCamera camera, bool fractionalOdd, int maxCells)
        {
            var r = new ErrorResult();
            bool apart = !ReferenceEquals(surface, exact);
            Float4x4 m = camera != null ? camera.ObjectToClipFloat() : default;
            // Clip coordinates of a drawn vertex as the GPU forms them: float position, float matrix.
            double[] ClipF(double[] p)
            {
                Float4 c = m * new Float4((float)p[0], (float)p[1], (float)p[2], 1f);
                return new double[] { c.x, c.y, c.z, c.w };
            }
            double ScreenPixels(double[] ca, double[] cb, double[] e)
            {
                double cx = 0.5 * (ca[0] + cb[0]), cy = 0.5 * (ca[1] + cb[1]), cw = 0.5 * (ca[3] + cb[3]);
                double[] pe = camera.ToPixels(e);
                double px = (cx / cw * 0.5 + 0.5) * camera.Width, py = (0.5 - cy / cw * 0.5) * camera.Height;
                return Math.Sqrt((px - pe[0]) * (px - pe[0]) + (py - pe[1]) * (py - pe[1]));
            }
            if (f.culled || f.e0 <= 0 || f.e1 <= 0 || f.e2 <= 0 || f.e3 <= 0) { r.CulledPatches = 1; return r; }
            Func<double, double[]> cut = fractionalOdd ? (Func<double, double[]>)TessellationCells.FractionalOdd : TessellationCells.Integer;
            double[] us = cut(f.i0), vs = cut(f.i1);
            int nu = us.Length - 1, nv = vs.Length - 1;
            // fractional_odd: the inside grid as if it reached the border (a model count); integer:
            // the tessellator's exact count, transition rings included.
            r.Triangles = fractionalOdd ? 2L * nu * nv : TessellationCells.IntegerTriangles(f);
            int stride = Math.Max(1, (int)Math.Ceiling(Math.Sqrt((double)nu * nv / maxCells)));

            void Sample(double[] a, double[] b, double[] exactAt)   // a, b: interpolated end points; exactAt: (s, t)
            {
                double[] e = exact(patch, exactAt[0], exactAt[1]);
                double dx = 0.5 * (a[0] + b[0]) - e[0], dy = 0.5 * (a[1] + b[1]) - e[1], dz = 0.5 * (a[2] + b[2]) - e[2];
                double d = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                double px = 0;
                if (camera != null)
                {
                    if (!camera.Visible(e)) return;
                    px = d * camera.PixelsPerUnit(e);
                    if (apart)
                    {
                        double sc = ScreenPixels(ClipF(a), ClipF(b), e);
                        r.MaxScreenPixels = Math.Max(r.MaxScreenPixels, sc);
                        r.RmsScreenPixels += sc * sc;
                    }
                }
                r.Samples++;
                if (Debug && px > r.MaxPixels) Console.Error.WriteLine(FormattableString.Invariant($"patch {patch} at ({exactAt[0]:G4}, {exactAt[1]:G4}) d {d:G4} px {px:G4}"));
                r.MaxWorld = Math.Max(r.MaxWorld, d); r.RmsWorld += d * d;
                r.MaxPixels = Math.Max(r.MaxPixels, px); r.RmsPixels += px * px;
            }

            // Inside grid: vertices, then per cell its lower and left edges' midpoints (the last row
            // and column also their upper/right ones) and the centre on both diagonals.
            var rowsCache = new Dictionary<int, double[][]>();
            double[][] Row(int j)
            {
                if (rowsCache.TryGetValue(j, out var row)) return row;
                row = new double[nu + 1][];
                for (int i = 0; i <= nu; i++) row[i] = surface(patch, us[i], vs[j]);
                return rowsCache[j] = row;
            }
            for (int j = 0; j < nv; j += stride)
            {
                rowsCache.Clear();
                double[][] lo = Row(j), hi = Row(j + 1);
                for (int i = 0; i < nu; i += stride)
                {
                    double um = 0.5 * (us[i] + us[i + 1]), vm = 0.5 * (vs[j] + vs[j + 1]);
                    Sample(lo[i], lo[i + 1], new[] { um, vs[j] });
                    Sample(lo[i], hi[i], new[] { us[i], vm });
                    if (j + stride >= nv) Sample(hi[i], hi[i + 1], new[] { um, vs[j + 1] });
                    if (i + stride >= nu) Sample(lo[i + 1], hi[i + 1], new[] { us[i + 1], vm });
                    Sample(lo[i], hi[i + 1], new[] { um, vm });
                    Sample(lo[i + 1], hi[i], new[] { um, vm });
                    if (apart) Sample(lo[i], lo[i], new[] { us[i], vs[j] });   // the vertex itself (octaves left out, rounding)
                }
            }
            // Border segments at the edge factors.
            BorderEdge(surface, patch, cut(f.e0), s => new[] { 0.0, s }, Sample, stride);
            BorderEdge(surface, patch, cut(f.e1), s => new[] { s, 0.0 }, Sample, stride);
            BorderEdge(surface, patch, cut(f.e2), s => new[] { 1.0, s }, Sample, stride);
            BorderEdge(surface, patch, cut(f.e3), s => new[] { s, 1.0 }, Sample, stride);
            return r;
        }

        static void BorderEdge(Func<int, double, double, double[]> surface, int patch, double[] xs, Func<double, double[]> at,
                               Action<double[], double[], double[]> sample, int stride)
        {
            for (int k = 0; k + 1 < xs.Length; k += stride)
            {
                double[] a = at(xs[k]), b = at(xs[k + 1]), m = at(0.5 * (xs[k] + xs[k + 1]));
                sample(surface(patch, a[0], a[1]), surface(patch, b[0], b[1]), m);
            }
        }
    }
}
