using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A vertex of a tile, as its cell's cache records: the bilinear blend of slots a, b (along the
    /// first axis at t.x) and c, d (the same, one step along the second axis), then of the two at
    /// t.y. t = 0 reads a alone; t.y = 0 reads a and b. HLSL <c>CellPointBlend</c>.
    /// </summary>
    internal struct CellPointBlend : IEquatable<CellPointBlend>
    {
        public int a, b, c, d;
        public Float2 t;

        public bool Equals(CellPointBlend o) => a == o.a && b == o.b && c == o.c && d == o.d && t.Equals(o.t);
        public override bool Equals(object obj) => obj is CellPointBlend o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(a, b, c, d, t);
        public override string ToString() => FormattableString.Invariant($"({a}, {b}; {c}, {d}) at {t}");
    }

    /// <summary>
    /// Anchored tiles drawn from whole cells (internals.md, "Vertex cache"), name for name as
    /// <c>Shaders/Cache/ClippedCell.hlsl</c>. The vertex cache holds each lattice cell whole; a tile the
    /// range clips keeps <c>[s0, s1]</c> of its cell per axis (<see cref="TileLattice.TileKeptCellSpan"/>)
    /// and draws the segments of its cell's lines that meet it: the points on the cell's lines are the
    /// cell's own, and only the points on the range's edge are blended from the two cell points either
    /// side. So a pan that keeps the cells changes nothing in the cache, and no vertex but those on the
    /// range's edge moves (no swimming in the clipped tiles either).
    /// </summary>
    internal static class ClippedCell
    {
        /// <summary>Exactly (0, 1, 0, 1): the tile is its whole cell. HLSL <c>CellKeptWhole</c>.</summary>
        public static bool CellKeptWhole(Float4 kept) => kept.x == 0f && kept.y == 1f && kept.z == 0f && kept.w == 1f;

        /// <summary>
        /// The segments of a line of n that meet [s0, s1] (cell parameters): ceil(s1 n) - floor(s0 n).
        /// n when the whole line is kept. HLSL <c>KeptSegments</c>.
        /// </summary>
        public static float KeptSegments(float n, float s0, float s1) => MathF.Ceiling(s1 * n) - MathF.Floor(s0 * n);

        /// <summary>
        /// HLSL <c>ClippedTileFactors</c>: the integer factors of a tile that keeps
        /// <paramref name="kept"/> = (s0.x, s1.x, s0.y, s1.y) of a cell drawn at
        /// <paramref name="cell"/> (integer factors, as <see cref="VertexCache.IntegerFactors"/> gives).
        /// A line on a cell line keeps its <see cref="KeptSegments"/>; an edge on the range's edge
        /// takes the tile's kept inside count across it. No segment is longer than the cell's, so the
        /// cell's error bound holds; tiles sharing an edge share its cell line and its part, so they
        /// agree on its factor. Then raised as the tessellator draws it (an inside 1 is 2 unless all
        /// are 1). Whole: the cell's, bit for bit. Culled, or a tile without area: culled.
        /// </summary>
        public static TileFactorSet ClippedTileFactors(TileFactorSet cell, Float4 kept)
        {
            if (cell.IsCulled || CellKeptWhole(kept)) return cell;
            if (kept.x == kept.y || kept.z == kept.w) return default;
            var inside = new Float2(KeptSegments(cell.inside.x, kept.x, kept.y), KeptSegments(cell.inside.y, kept.z, kept.w));
            var edge = new Float4(
                kept.x > 0f ? inside.y : KeptSegments(cell.edge.x, kept.z, kept.w),
                kept.z > 0f ? inside.x : KeptSegments(cell.edge.y, kept.x, kept.y),
                kept.y < 1f ? inside.y : KeptSegments(cell.edge.z, kept.z, kept.w),
                kept.w < 1f ? inside.x : KeptSegments(cell.edge.w, kept.x, kept.y));
            return VertexCache.DrawnFactors(new TileFactorSet(edge, inside));
        }

        /// <summary>
        /// Where point k of the d a tile draws over [s0, s1] of a line of n segments sits, in that
        /// line's units (a whole number: on one of its points): the ends at s0 n and s1 n, the others
        /// on the line's own points from floor(s0 n) + 1 on. An inside count of 1 drawn as 2 puts its
        /// middle point halfway. HLSL <c>KeptLinePosition</c>.
        /// </summary>
        public static float KeptLinePosition(float n, float s0, float s1, float d, float k)
        {
            if (k == 0f) return s0 * n;
            if (k == d) return s1 * n;
            if (KeptSegments(n, s0, s1) < d) return 0.5f * (s0 + s1) * n;
            return MathF.Floor(s0 * n) + k;
        }

        /// <summary>One record, unblended. HLSL <c>CellSlotBlend</c>.</summary>
        public static CellPointBlend CellSlotBlend(int slot) => new CellPointBlend { a = slot, b = slot, c = slot, d = slot };

        /// <summary>Point x (line units) of edge e: its point floor(x), blended towards the next by the rest. HLSL <c>CellEdgeBlend</c>.</summary>
        public static CellPointBlend CellEdgeBlend(int edge, float x, int limit)
        {
            float a = MathF.Floor(x);
            int slot = VertexCache.EdgeSlot(edge, (int)a, limit);
            CellPointBlend p = CellSlotBlend(slot);
            if (x > a) { p.b = slot + 1; p.t.x = x - a; }
            return p;
        }

        /// <summary>
        /// The cell's inside grid (its border included) at (xu, xv), in grid units: bilinear between
        /// the four grid points around it, or fewer where it lies on a grid line. HLSL <c>CellGridBlend</c>.
        /// </summary>
        public static CellPointBlend CellGridBlend(float xu, float xv, float insideU)
        {
            float au = MathF.Floor(xu), av = MathF.Floor(xv);
            int w = (int)insideU;
            int slot = VertexCache.InteriorSlot((int)au, (int)av, w);
            CellPointBlend p = CellSlotBlend(slot);
            if (xu > au) { p.b = slot + 1; p.t.x = xu - au; }
            if (xv > av)
            {
                p.c = slot + w + 1;
                p.d = xu > au ? p.c + 1 : p.c;
                p.t.y = xv - av;
            }
            return p;
        }

        /// <summary>Edge e's factor of a factor set's edges. HLSL <c>CellFactorOfEdge</c>.</summary>
        static float CellFactorOfEdge(Float4 edge, int e) => e == 0 ? edge.x : e == 1 ? edge.y : e == 2 ? edge.z : edge.w;

        /// <summary>
        /// HLSL <c>CellPoint</c>: the records the vertex at <paramref name="tess"/> of a tile drawn at
        /// <paramref name="tile"/> (<see cref="ClippedTileFactors"/>) reads from its cell's slots
        /// (cell drawn at <paramref name="cell"/>). A whole tile reads <see cref="VertexCache.Slot"/>.
        /// Clipped: a corner on two cell lines is the cell's; a corner on one cell line lies on it, at
        /// the other axis's s0 or s1; the range's own corner blends the grid; an edge on a cell line
        /// reads that line's points; an edge on the range's edge blends the two grid columns (or rows)
        /// either side at each grid row; inside points are the grid's own.
        /// </summary>
        public static CellPointBlend CellPoint(Float2 tess, TileFactorSet tile, TileFactorSet cell, Float4 kept, int limit)
        {
            if (CellKeptWhole(kept)) return CellSlotBlend(VertexCache.Slot(tess, tile, limit));
            bool u0 = tess.x == 0f, u1 = tess.x == 1f, v0 = tess.y == 0f, v1 = tess.y == 1f;
            bool onU = u0 || u1, onV = v0 || v1;
            float su = u0 ? kept.x : kept.y, sv = v0 ? kept.z : kept.w;   // the cell parameter of the side at tess
            bool clipU = u0 ? kept.x > 0f : kept.y < 1f, clipV = v0 ? kept.z > 0f : kept.w < 1f;
            if (onU && onV)
            {
                if (!clipU && !clipV) return CellSlotBlend(VertexCache.Slot(tess, cell, limit));
                if (!clipV) { int e = v0 ? 1 : 3; return CellEdgeBlend(e, su * CellFactorOfEdge(cell.edge, e), limit); }
                if (!clipU) { int e = u0 ? 0 : 2; return CellEdgeBlend(e, sv * CellFactorOfEdge(cell.edge, e), limit); }
                return CellGridBlend(su * cell.inside.x, sv * cell.inside.y, cell.inside.x);
            }
            if (onU)
            {
                int e = u0 ? 0 : 2;
                float d = CellFactorOfEdge(tile.edge, e), k = VertexCache.RoundToPoint(tess.y * d);
                return clipU ? CellGridBlend(su * cell.inside.x, KeptLinePosition(cell.inside.y, kept.z, kept.w, d, k), cell.inside.x)
                             : CellEdgeBlend(e, KeptLinePosition(CellFactorOfEdge(cell.edge, e), kept.z, kept.w, d, k), limit);
            }
            if (onV)
            {
                int e = v0 ? 1 : 3;
                float d = CellFactorOfEdge(tile.edge, e), k = VertexCache.RoundToPoint(tess.x * d);
                return clipV ? CellGridBlend(KeptLinePosition(cell.inside.x, kept.x, kept.y, d, k), sv * cell.inside.y, cell.inside.x)
                             : CellEdgeBlend(e, KeptLinePosition(CellFactorOfEdge(cell.edge, e), kept.x, kept.y, d, k), limit);
            }
            float i = VertexCache.RoundToPoint(tess.x * tile.inside.x), j = VertexCache.RoundToPoint(tess.y * tile.inside.y);
            return CellGridBlend(KeptLinePosition(cell.inside.x, kept.x, kept.y, tile.inside.x, i),
                                 KeptLinePosition(cell.inside.y, kept.z, kept.w, tile.inside.y, j), cell.inside.x);
        }

        /// <summary>
        /// Where the record in <paramref name="slot"/> of a cell drawn at <paramref name="cell"/> was
        /// evaluated, in the cell's tess coordinates: the point <see cref="VertexCache.TilePoints"/>
        /// (anchored) gives that slot. HLSL <c>CellSlotTess</c>.
        /// </summary>
        public static Float2 CellSlotTess(int slot, TileFactorSet cell, int limit)
        {
            int grid = VertexCache.EdgeSlot(0, 0, limit);
            if (slot < grid)
            {
                int w = (int)cell.inside.x + 1;
                return new Float2((slot % w) / cell.inside.x, (slot / w) / cell.inside.y);
            }
            int e = (slot - grid) / (limit + 1);
            return VertexCache.EdgeTess(e, slot - VertexCache.EdgeSlot(e, 0, limit), CellFactorOfEdge(cell.edge, e));
        }

        /// <summary>
        /// Where the vertex that blends <paramref name="p"/> lies in its cell, tess coordinates: its
        /// records' points blended as their values are. The Patch Id view looks the patch up there
        /// (a record has no patch index). HLSL <c>CellPointTess</c>.
        /// </summary>
        public static Float2 CellPointTess(CellPointBlend p, TileFactorSet cell, int limit)
        {
            Float2 ab = GMath.lerp(CellSlotTess(p.a, cell, limit), CellSlotTess(p.b, cell, limit), p.t.x);
            Float2 cd = GMath.lerp(CellSlotTess(p.c, cell, limit), CellSlotTess(p.d, cell, limit), p.t.x);
            return GMath.lerp(ab, cd, p.t.y);
        }
    }
}
