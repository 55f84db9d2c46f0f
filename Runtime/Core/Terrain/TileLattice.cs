using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Tiles anchored to the terrain (internals.md, "Anchored tiles"). Mirrors
    /// <c>Shaders/Terrain/TileLattice.hlsl</c>, same names, step for step in float.
    /// <para>The tiles are the cells of the lattice of the range <c>_TileLattice</c> had when anchored;
    /// the range meets at most M + 1 cells per axis, each clipped to it, so a pan changes only the
    /// clipped cells. Cell k sits in slot k mod (M + 1) per axis.</para>
    /// </summary>
    internal static class TileLattice
    {
        /// <summary>
        /// How much wider than the lattice (relative) the range may be: a pan rounds the range's float
        /// width up or down by an ulp or so, and the last tile, which ends at g, takes the excess.
        /// </summary>
        public const float WidthSlack = 1f / 1024f;

        /// <summary>Whether <paramref name="lattice"/> anchors the tiles: 0 leaves them on the range.</summary>
        public static bool IsAnchored(Float4 lattice) => lattice.z != lattice.x;

        /// <summary>
        /// Checks a <c>_TileLattice</c> for <paramref name="range"/> and M = <paramref name="tiles"/>:
        /// 0, or finite with positive widths no narrower than the range's, up to <see cref="WidthSlack"/>
        /// (so M + 1 cells cover it).
        /// The message names <paramref name="field"/> and the values.
        /// </summary>
        public static void Validate(Float4 lattice, Float4 range, float tiles, string field)
        {
            if (lattice.x == 0f && lattice.y == 0f && lattice.z == 0f && lattice.w == 0f) return;
            if (!lattice.IsFinite || !(lattice.z > lattice.x) || !(lattice.w > lattice.y))
                throw new ArgumentException(FormattableString.Invariant($"{field} {lattice} must be 0 or a range (c, d, g, h) with g > c and h > d, all finite"), field);
            if (!(tiles >= 1f) || tiles != GMath.floor(tiles))
                throw new ArgumentException(FormattableString.Invariant($"{field}: the tile count M ({tiles:R}) must be a whole number >= 1 to anchor tiles"), field);
            if (!Covers(lattice.z - lattice.x, range.z - range.x) || !Covers(lattice.w - lattice.y, range.w - range.y))
                throw new ArgumentException(FormattableString.Invariant($"{field} {lattice} is narrower than the range {range}: anchor the tiles again (TileLattice.Follow)"), field);
        }

        /// <summary>Tiles per axis: M laid over the range, M + 1 anchored.</summary>
        public static int TilesAcross(TerrainParams p) => (int)p.tess.x + (IsAnchored(p.tileLattice) ? 1 : 0);

        /// <summary>
        /// The lattice the renderer keeps while the range only pans: <paramref name="current"/> while
        /// the range fits it and is no more than one tile narrower (a zoom of less than 1/M), else the
        /// range itself (a fresh anchor; every tile is evaluated again). Per axis, in the range's
        /// float coordinates (both relative to the same origin).
        /// </summary>
        public static Float4 Follow(Float4 current, Float4 range, float tiles)
        {
            if (!IsAnchored(current) || !current.IsFinite) return range;
            if (!Fits(current.z - current.x, range.z - range.x, tiles) || !Fits(current.w - current.y, range.w - range.y, tiles))
                return range;
            return current;
        }

        static bool Fits(float latticeWidth, float rangeWidth, float tiles) =>
            Covers(latticeWidth, rangeWidth) && rangeWidth > latticeWidth * (1f - 1f / tiles);

        static bool Covers(float latticeWidth, float rangeWidth) => rangeWidth <= latticeWidth * (1f + WidthSlack);

        // ---------------------------------------------------------------- one axis

        /// <summary>
        /// Point s (0..1) of lattice cell k on one axis: <c>lo + ((k + s) / M)(hi - lo)</c>,
        /// RangeCoordinate's formula (k + s first, so k + 1 at s = 0 and k at s = 1 agree exactly).
        /// </summary>
        public static float LatticePoint(float lo, float hi, float tiles, int k, float s)
        {
            float sum = (float)k + s;
            return lo + (sum / tiles) * (hi - lo);
        }

        /// <summary>Lattice line k: the start of cell k.</summary>
        public static float LatticeLine(float lo, float hi, float tiles, int k) => LatticePoint(lo, hi, tiles, k, 0f);

        /// <summary>
        /// The cell holding c: k with <c>LatticeLine(k) &lt;= c &lt; LatticeLine(k + 1)</c>. The
        /// estimate from a division is corrected against the lines themselves, so every tile of a
        /// frame agrees with the lines it draws.
        /// </summary>
        public static int FirstCell(float c, float lo, float hi, float tiles)
        {
            int k = (int)GMath.floor((c - lo) / (hi - lo) * tiles);
            if (LatticeLine(lo, hi, tiles, k) > c) k -= 1;
            else if (LatticeLine(lo, hi, tiles, k + 1) <= c) k += 1;
            return k;
        }

        /// <summary>
        /// The part of cell <c>k0 + i</c> (i = 0..M) inside [c, g]: the first tile starts at c, the
        /// last ends at g, and cells past g shrink to g (a range narrower than the lattice).
        /// <paramref name="whole"/>: the span is the whole cell.
        /// </summary>
        public static Float2 AxisSpan(float c, float g, float lo, float hi, float tiles, int k0, int i, out bool whole)
        {
            int k = k0 + i;
            float a = LatticeLine(lo, hi, tiles, k), b = LatticeLine(lo, hi, tiles, k + 1);
            float l = i == 0 ? c : GMath.clamp(a, c, g);
            float h = i == (int)tiles ? g : GMath.clamp(b, c, g);
            whole = l == a && h == b;
            return new Float2(l, h);
        }

        /// <summary>
        /// Point s of a tile on one axis, from its <see cref="AxisSpan"/> and cell k. A whole cell
        /// uses the lattice formula, so its points do not move while the range pans; a clipped one
        /// <c>(1 - s) l + s h</c>, exact at both ends, so a line it shares with a whole neighbour is
        /// bit-identical.
        /// </summary>
        public static float AxisPoint(Float2 span, bool whole, float lo, float hi, float tiles, int k, float s) =>
            whole ? LatticePoint(lo, hi, tiles, k, s) : (1f - s) * span.x + s * span.y;

        /// <summary>The tile index i (0..M) that slot <paramref name="slot"/> holds: <c>(slot - k0) mod (M + 1)</c>.</summary>
        public static int TileOfSlot(int slot, int k0, int across)
        {
            int r = (slot - k0) % across;
            return r < 0 ? r + across : r;
        }

        // ---------------------------------------------------------------- both axes

        /// <summary>
        /// The global point of tess coordinate (s, t) in the tile that draw patch (slot)
        /// <paramref name="slot"/> holds: <see cref="RangeMapping.ToTerrainPoint"/> when the tiles lie
        /// on the range, else the anchored tile's point. HLSL <c>TileToTerrainPoint</c>.
        /// </summary>
        public static TerrainPoint TileToTerrainPoint(TerrainParams p, int slot, float s, float t)
        {
            int across = TilesAcross(p);
            if (!IsAnchored(p.tileLattice))
                return RangeMapping.ToTerrainPoint(p.range, p.rangeOrigin, across, slot % across, slot / across, s, t);
            Float4 span = AnchoredTileSpan(p, slot, out int cellX, out int cellY, out bool wholeX, out bool wholeY);
            float m = p.tess.x;
            Float4 lat = p.tileLattice;
            var local = new Float2(
                p.rangeOrigin.z + AxisPoint(new Float2(span.x, span.z), wholeX, lat.x, lat.z, m, cellX, s),
                p.rangeOrigin.w + AxisPoint(new Float2(span.y, span.w), wholeY, lat.y, lat.w, m, cellY, t));
            return new TerrainPoint(p.rangeOrigin.xy, local);
        }

        /// <summary>
        /// The part of the terrain, relative to the origin, that slot <paramref name="slot"/> draws when
        /// anchored: (l.x, l.y, h.x, h.y). HLSL <c>TileSpan</c>.
        /// </summary>
        public static Float4 TileSpan(TerrainParams p, int slot)
        {
            if (!IsAnchored(p.tileLattice)) throw new InvalidOperationException("TileSpan: the tiles are not anchored (tileLattice is 0)");
            return AnchoredTileSpan(p, slot, out _, out _, out _, out _);
        }

        /// <summary>
        /// Whether slot <paramref name="slot"/>'s anchored tile has no area (a cell past g, or the last
        /// one when the range ends on a lattice line): culled. HLSL <c>TileEmpty</c>.
        /// </summary>
        public static bool TileEmpty(TerrainParams p, int slot)
        {
            if (!IsAnchored(p.tileLattice)) return false;
            Float4 span = TileSpan(p, slot);
            return span.x == span.z || span.y == span.w;
        }

        // ---------------------------------------------------------------- the cells the factors are decided on

        /// <summary>Lattice cell (<paramref name="cellX"/>, <paramref name="cellY"/>) relative to the origin: (l.x, l.y, h.x, h.y). HLSL <c>LatticeCell</c>.</summary>
        public static Float4 LatticeCell(TerrainParams p, int cellX, int cellY)
        {
            float m = p.tess.x;
            Float4 lat = p.tileLattice;
            return new Float4(LatticeLine(lat.x, lat.z, m, cellX), LatticeLine(lat.y, lat.w, m, cellY),
                              LatticeLine(lat.x, lat.z, m, cellX + 1), LatticeLine(lat.y, lat.w, m, cellY + 1));
        }

        /// <summary>The whole cell slot <paramref name="slot"/> holds (anchored only): its tile before clipping. HLSL <c>CellSpan</c>.</summary>
        public static Float4 CellSpan(TerrainParams p, int slot)
        {
            if (!IsAnchored(p.tileLattice)) throw new InvalidOperationException("CellSpan: the tiles are not anchored (tileLattice is 0)");
            AnchoredTileSpan(p, slot, out int cellX, out int cellY, out _, out _);
            return LatticeCell(p, cellX, cellY);
        }

        /// <summary>
        /// The global point of tess coordinate (s, t) in the whole cell slot <paramref name="slot"/>
        /// holds: the tile's own point where the tile is the whole cell (bit for bit), else also
        /// beyond its clipped side; laid over the range, the tile's point. The adaptive factors
        /// sample the cell (<see cref="TileFactors"/>), so a pan changes no cell's samples. HLSL
        /// <c>CellToTerrainPoint</c>.
        /// </summary>
        public static TerrainPoint CellToTerrainPoint(TerrainParams p, int slot, float s, float t)
        {
            if (!IsAnchored(p.tileLattice)) return TileToTerrainPoint(p, slot, s, t);
            AnchoredTileSpan(p, slot, out int cellX, out int cellY, out _, out _);
            float m = p.tess.x;
            Float4 lat = p.tileLattice;
            var local = new Float2(p.rangeOrigin.z + LatticePoint(lat.x, lat.z, m, cellX, s),
                                   p.rangeOrigin.w + LatticePoint(lat.y, lat.w, m, cellY, t));
            return new TerrainPoint(p.rangeOrigin.xy, local);
        }

        /// <summary>
        /// The part of its cell slot <paramref name="slot"/>'s tile keeps, in the cell's own
        /// parameters: (s0.x, s1.x, s0.y, s1.y), exactly (0, 1, 0, 1) on whole axes (and laid over the
        /// range), so a whole tile reads its cell's slots as they are (<see cref="ClippedCell"/>).
        /// Tiles of one column share x, of one row y: tiles sharing an edge agree on its part.
        /// HLSL <c>TileKeptCellSpan</c>.
        /// </summary>
        public static Float4 TileKeptCellSpan(TerrainParams p, int slot)
        {
            if (!IsAnchored(p.tileLattice)) return new Float4(0f, 1f, 0f, 1f);
            Float4 span = AnchoredTileSpan(p, slot, out int cellX, out int cellY, out _, out _);
            Float4 c = LatticeCell(p, cellX, cellY);
            return new Float4(CellParameter(span.x, c.x, c.z), CellParameter(span.z, c.x, c.z),
                              CellParameter(span.y, c.y, c.w), CellParameter(span.w, c.y, c.w));
        }

        /// <summary>
        /// How much of its cell slot <paramref name="slot"/>'s tile keeps along x and y: the width of
        /// its <see cref="TileKeptCellSpan"/>, exactly 1 on a whole axis (and laid over the range),
        /// never above 1. The domain-stage path scales the cell's factors by it
        /// (<see cref="TileFactors.TileFactorsOfCell"/>). HLSL <c>TileKeptFraction</c>.
        /// </summary>
        public static Float2 TileKeptFraction(TerrainParams p, int slot)
        {
            Float4 kept = TileKeptCellSpan(p, slot);
            return new Float2(kept.y - kept.x, kept.w - kept.z);
        }

        /// <summary>
        /// What the vertex cache's kernels read of <c>_Range</c>: the range itself, or anchored only
        /// the first cell on each axis, (k0.x, k0.y, 0, 0): their keys, samples and slots are the
        /// cells' (<see cref="ClippedCell"/>), so a pan that keeps the first cells changes nothing they
        /// compute, and a renderer need not dispatch them.
        /// </summary>
        public static Float4 KernelRange(TerrainParams p)
        {
            if (!IsAnchored(p.tileLattice)) return p.range;
            return new Float4(FirstCell(p.range.x, p.tileLattice.x, p.tileLattice.z, p.tess.x),
                              FirstCell(p.range.y, p.tileLattice.y, p.tileLattice.w, p.tess.x), 0f, 0f);
        }

        /// <summary>Where x lies in the cell [lo, hi]: exactly 0 and 1 at its lines, else (x - lo) / (hi - lo). HLSL <c>CellParameter</c>.</summary>
        public static float CellParameter(float x, float lo, float hi) => x == lo ? 0f : x == hi ? 1f : (x - lo) / (hi - lo);

        /// <summary>
        /// The edge lengths of slot <paramref name="slot"/>'s cell along x and y, in terrain units
        /// (the factors' noise term): from the lattice lines, so a shared edge's length is its row's or
        /// column's. Laid over the range: <c>(range width) / M</c>. HLSL <c>CellEdgeLengths</c>.
        /// </summary>
        public static Float2 CellEdgeLengths(TerrainParams p, int slot)
        {
            if (!IsAnchored(p.tileLattice))
                return new Float2((p.range.z - p.range.x) / p.tess.x, (p.range.w - p.range.y) / p.tess.x);
            Float4 c = CellSpan(p, slot);
            return new Float2(c.z - c.x, c.w - c.y);
        }

        /// <summary>
        /// The width whose M tiles set the vertex spacing: the lattice's when anchored (a pan keeps
        /// it, so the octave count and the cached vertices stay put), else the range's.
        /// </summary>
        public static float LayoutWidth(TerrainParams p) =>
            IsAnchored(p.tileLattice) ? p.tileLattice.z - p.tileLattice.x : p.range.z - p.range.x;

        /// <summary>
        /// The anchored tile of slot <paramref name="slot"/>: its span (l.x, l.y, h.x, h.y), its cell
        /// on each axis and whether each axis holds the whole cell. HLSL <c>AnchoredTileSpan</c>.
        /// </summary>
        static Float4 AnchoredTileSpan(TerrainParams p, int slot, out int cellX, out int cellY, out bool wholeX, out bool wholeY)
        {
            int across = TilesAcross(p);
            float m = p.tess.x;
            Float4 r = p.range, lat = p.tileLattice;
            int k0x = FirstCell(r.x, lat.x, lat.z, m), k0y = FirstCell(r.y, lat.y, lat.w, m);
            int i = TileOfSlot(slot % across, k0x, across), j = TileOfSlot(slot / across, k0y, across);
            Float2 x = AxisSpan(r.x, r.z, lat.x, lat.z, m, k0x, i, out wholeX);
            Float2 y = AxisSpan(r.y, r.w, lat.y, lat.w, m, k0y, j, out wholeY);
            cellX = k0x + i;
            cellY = k0y + j;
            return new Float4(x.x, y.x, x.y, y.y);
        }
    }
}
