// Tiles anchored to the terrain (Documentation~/internals.md, "Anchored tiles"). Mirrors
// Runtime/Core/Terrain/TileLattice.cs, same names, step for step.
//
// _TileLattice = 0: the M x M tiles lie on the range (the paper's layout). Else it is the range the
// tiles were anchored at, whose cells form a lattice fixed in terrain space; tile i is cell k0 + i
// clipped to the range, so a pan moves only the clipped cells (no swimming). Cell k sits in slot
// k mod (M + 1) per axis. A clipped tile's factors come from its whole cell's (TileFactorsOfCell).
//
// Every function takes the layout it works on (TileLayout) as a parameter and reads no global: the
// stage entry points pass the frame's (FrameTileLayout, TerrainInputs.hlsl), and a level of detail
// passes its own range and lattice (internals.md, "Levels of detail"). Core passes TerrainParams.
#ifndef GT_TILE_LATTICE_INCLUDED
#define GT_TILE_LATTICE_INCLUDED

#include "../Library/RangeMapping.hlsl"

// The tiles of one draw: what Core's TileLattice reads of TerrainParams.
struct TileLayout
{
    float4 range;    // (c, d, g, h) relative to the origin (_Range, or one level's range)
    float4 lattice;  // 0 (tiles on the range), or the range the tiles were anchored at (_TileLattice)
    float4 origin;   // (O.x hi, O.y hi, O.x lo, O.y lo) (_RangeOrigin)
    float tiles;     // M (a float: RangeCoordinate divides by it)
};

TileLayout MakeTileLayout(float4 range, float4 lattice, float4 origin, float tiles)
{
    TileLayout l;
    l.range = range;
    l.lattice = lattice;
    l.origin = origin;
    l.tiles = tiles;
    return l;
}

// Whether the tiles are anchored to the terrain: a nonzero lattice. Core TileLattice.IsAnchored.
bool IsAnchored(float4 lattice) { return lattice.z != lattice.x; }
// Tiles (draw patches, cache tiles) per axis: M, or M + 1 anchored. Core TileLattice.TilesAcross.
uint TilesAcross(TileLayout l) { return (uint)l.tiles + (IsAnchored(l.lattice) ? 1u : 0u); }
// The width whose M tiles set the vertex spacing: the lattice's when anchored (a pan keeps it, so
// the octave count and the cached vertices stay put), else the range's. Core TileLattice.LayoutWidth.
float LayoutWidth(TileLayout l) { return IsAnchored(l.lattice) ? l.lattice.z - l.lattice.x : l.range.z - l.range.x; }

// --- One axis (parameters in) ---------------------------------------------------------------------

// Point s of lattice cell k: lo + ((k + s) / M)(hi - lo), RangeCoordinate's formula (k + s first,
// so cell k at s = 1 and cell k + 1 at s = 0 form the same float).
float LatticePoint(float lo, float hi, float tiles, int k, float s)
{
    precise float sum = float(k) + s;
    precise float p = lo + (sum / tiles) * (hi - lo);
    return p;
}

float LatticeLine(float lo, float hi, float tiles, int k) { return LatticePoint(lo, hi, tiles, k, 0.0); }

// The cell holding c, corrected against the lines themselves (a division alone may be off by one).
int FirstCell(float c, float lo, float hi, float tiles)
{
    int k = (int)floor((c - lo) / (hi - lo) * tiles);
    if (LatticeLine(lo, hi, tiles, k) > c) k -= 1;
    else if (LatticeLine(lo, hi, tiles, k + 1) <= c) k += 1;
    return k;
}

// The part of cell k0 + i (i = 0..M) inside [c, g]; cells past g shrink to g. whole: the span is
// the whole cell.
float2 AxisSpan(float c, float g, float lo, float hi, float tiles, int k0, int i, out bool whole)
{
    int k = k0 + i;
    float a = LatticeLine(lo, hi, tiles, k), b = LatticeLine(lo, hi, tiles, k + 1);
    float l = i == 0 ? c : clamp(a, c, g);
    float h = i == (int)tiles ? g : clamp(b, c, g);
    whole = l == a && h == b;
    return float2(l, h);
}

// Point s of a tile on one axis, from its AxisSpan and cell k. A whole cell keeps the lattice
// formula (bit-stable while the range pans); a clipped one interpolates its span, exact at both
// ends, so a line shared with a whole neighbour matches.
float AxisPoint(float2 span, bool whole, float lo, float hi, float tiles, int k, float s)
{
    if (whole) return LatticePoint(lo, hi, tiles, k, s);
    precise float p = (1.0 - s) * span.x + s * span.y;
    return p;
}

// The tile index (0..M) slot `slot` holds: (slot - k0) mod (M + 1), never negative.
int TileOfSlot(int slot, int k0, int across)
{
    int r = (slot - k0) % across;
    return r < 0 ? r + across : r;
}

// --- Both axes, from a layout ---------------------------------------------------------------

// The anchored tile of slot `slot`: its span (l.x, l.y, h.x, h.y), its cell on each axis and
// whether each axis holds the whole cell.
float4 AnchoredTileSpan(TileLayout l, uint slot, out int2 cell, out bool2 whole)
{
    int across = (int)TilesAcross(l);
    float m = l.tiles;
    float4 r = l.range, lat = l.lattice;
    int2 k0 = int2(FirstCell(r.x, lat.x, lat.z, m), FirstCell(r.y, lat.y, lat.w, m));
    int2 ij = int2(TileOfSlot((int)slot % across, k0.x, across), TileOfSlot((int)slot / across, k0.y, across));
    bool wholeX, wholeY;
    float2 x = AxisSpan(r.x, r.z, lat.x, lat.z, m, k0.x, ij.x, wholeX);
    float2 y = AxisSpan(r.y, r.w, lat.y, lat.w, m, k0.y, ij.y, wholeY);
    cell = k0 + ij;
    whole = bool2(wholeX, wholeY);
    return float4(x.x, y.x, x.y, y.y);
}

// The global point of tess coordinate `tess` in the tile of draw patch (slot) `slot`.
TerrainPoint TileToTerrainPoint(TileLayout l, uint slot, float2 tess)
{
    uint across = TilesAcross(l);
    if (!IsAnchored(l.lattice))
        return RangeToTerrainPoint(l.range, l.origin, l.tiles, uint2(slot % across, slot / across), tess);
    int2 cell;
    bool2 whole;
    float4 span = AnchoredTileSpan(l, slot, cell, whole);
    float m = l.tiles;
    float4 lat = l.lattice;
    TerrainPoint p;
    p.originHi = l.origin.xy;
    p.local = l.origin.zw + float2(AxisPoint(span.xz, whole.x, lat.x, lat.z, m, cell.x, tess.x),
                                   AxisPoint(span.yw, whole.y, lat.y, lat.w, m, cell.y, tess.y));
    return p;
}

// The terrain part (relative to the origin) slot `slot` draws, (l.x, l.y, h.x, h.y): anchored only.
float4 TileSpan(TileLayout l, uint slot)
{
    int2 cell;
    bool2 whole;
    return AnchoredTileSpan(l, slot, cell, whole);
}

// An anchored tile without area (a cell past g, or the last one when the range ends on a lattice
// line): culled, so its degenerate triangles cost nothing.
bool TileEmpty(TileLayout l, uint slot)
{
    if (!IsAnchored(l.lattice)) return false;
    float4 span = TileSpan(l, slot);
    return span.x == span.z || span.y == span.w;
}

// --- The cells the adaptive factors are decided on -------------------------------------------------

// Lattice cell (cell.x, cell.y), relative to the origin: (l.x, l.y, h.x, h.y).
float4 LatticeCell(TileLayout l, int2 cell)
{
    float m = l.tiles;
    float4 lat = l.lattice;
    return float4(LatticeLine(lat.x, lat.z, m, cell.x), LatticeLine(lat.y, lat.w, m, cell.y),
                  LatticeLine(lat.x, lat.z, m, cell.x + 1), LatticeLine(lat.y, lat.w, m, cell.y + 1));
}

// The whole cell slot `slot` holds (anchored only): its tile before clipping.
float4 CellSpan(TileLayout l, uint slot)
{
    int2 cell;
    bool2 whole;
    AnchoredTileSpan(l, slot, cell, whole);
    return LatticeCell(l, cell);
}

// The global point of tess coordinate `tess` in the whole cell slot `slot` holds: the tile's own
// point where the tile is the whole cell (the lattice formula, bit for bit), else also beyond its
// clipped side. Laid over the range, the tile's point. The adaptive factors sample the cell, not
// the clipped tile (TileFactors.hlsl), so a pan changes no cell's samples.
TerrainPoint CellToTerrainPoint(TileLayout l, uint slot, float2 tess)
{
    if (!IsAnchored(l.lattice)) return TileToTerrainPoint(l, slot, tess);
    int2 cell;
    bool2 whole;
    AnchoredTileSpan(l, slot, cell, whole);
    float m = l.tiles;
    float4 lat = l.lattice;
    TerrainPoint p;
    p.originHi = l.origin.xy;
    p.local = l.origin.zw + float2(LatticePoint(lat.x, lat.z, m, cell.x, tess.x),
                                   LatticePoint(lat.y, lat.w, m, cell.y, tess.y));
    return p;
}

// Where x lies in the cell [lo, hi]: exactly 0 and 1 at its lines, else (x - lo) / (hi - lo).
float CellParameter(float x, float lo, float hi) { return x == lo ? 0.0 : (x == hi ? 1.0 : (x - lo) / (hi - lo)); }

// The part of its cell the tile keeps, in the cell's own parameters: (s0.x, s1.x, s0.y, s1.y),
// exactly (0, 1, 0, 1) on whole axes (and laid over the range). Tiles of one column share x, of one
// row y: tiles sharing an edge agree on its part (ClippedCell.hlsl draws it from the whole cell).
float4 TileKeptCellSpan(TileLayout l, uint slot)
{
    if (!IsAnchored(l.lattice)) return float4(0.0, 1.0, 0.0, 1.0);
    int2 cell;
    bool2 whole;
    float4 span = AnchoredTileSpan(l, slot, cell, whole);
    float4 c = LatticeCell(l, cell);
    return float4(CellParameter(span.x, c.x, c.z), CellParameter(span.z, c.x, c.z),
                  CellParameter(span.y, c.y, c.w), CellParameter(span.w, c.y, c.w));
}

// How much of its cell the tile keeps along x and y: the width of its TileKeptCellSpan, exactly 1
// on a whole axis (and laid over the range), never above 1. Tiles sharing an edge share the row or
// column that decides it. The domain-stage path scales the cell's factors by it (TileFactorsOfCell).
float2 TileKeptFraction(TileLayout l, uint slot)
{
    float4 kept = TileKeptCellSpan(l, slot);
    return kept.yw - kept.xz;
}

// Edge lengths of the slot's cell along x and y in terrain units (the factors' noise term): from
// the lattice lines, so a shared edge's length is its row's or column's and both tiles see the
// same. Laid over the range: (range width) / M.
float2 CellEdgeLengths(TileLayout l, uint slot)
{
    if (!IsAnchored(l.lattice)) return (l.range.zw - l.range.xy) / l.tiles;
    float4 c = CellSpan(l, slot);
    return c.zw - c.xy;
}

#endif // GT_TILE_LATTICE_INCLUDED
