// Tiles anchored to the terrain (Documentation~/internals.md, "Anchored tiles"). Mirrors
// Runtime/Core/Terrain/TileLattice.cs, same names, step for step.
//
// _TileLattice = 0: the M x M tiles lie on the range (the paper's layout). Else it is the range the
// tiles were anchored at: its M x M cells, repeated beyond it, form a lattice fixed in terrain space;
// the current range (no wider) meets M + 1 cells per axis, and tile i is cell k0 + i clipped to the
// range. A pan moves only the clipped cells, so whole cells keep their points bit for bit (no
// swimming; the vertex cache keeps their vertices). Cell k sits in slot k mod (M + 1) per axis.
// A clipped tile's factors come from its whole cell's (TileFactors.hlsl, TileFactorsOfCell; with
// the vertex cache ClippedCell.hlsl, which also draws it from the whole cell's cached vertices), so
// a pan with the camera held samples nothing, and one that keeps the first cells dispatches nothing.
#ifndef GT_TILE_LATTICE_INCLUDED
#define GT_TILE_LATTICE_INCLUDED

#include "TerrainInputs.hlsl"
#include "../Library/RangeMapping.hlsl"

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

// --- Both axes, from the frame's inputs ---------------------------------------------------------------

// The anchored tile of slot `slot`: its span (l.x, l.y, h.x, h.y), its cell on each axis and
// whether each axis holds the whole cell.
float4 AnchoredTileSpan(uint slot, out int2 cell, out bool2 whole)
{
    int across = (int)TilesAcrossInt();
    float m = TileCount();
    int2 k0 = int2(FirstCell(_Range.x, _TileLattice.x, _TileLattice.z, m), FirstCell(_Range.y, _TileLattice.y, _TileLattice.w, m));
    int2 ij = int2(TileOfSlot((int)slot % across, k0.x, across), TileOfSlot((int)slot / across, k0.y, across));
    bool wholeX, wholeY;
    float2 x = AxisSpan(_Range.x, _Range.z, _TileLattice.x, _TileLattice.z, m, k0.x, ij.x, wholeX);
    float2 y = AxisSpan(_Range.y, _Range.w, _TileLattice.y, _TileLattice.w, m, k0.y, ij.y, wholeY);
    cell = k0 + ij;
    whole = bool2(wholeX, wholeY);
    return float4(x.x, y.x, x.y, y.y);
}

// The global point of tess coordinate `tess` in the tile of draw patch (slot) `slot`.
TerrainPoint TileToTerrainPoint(uint slot, float2 tess)
{
    uint across = TilesAcrossInt();
    if (!TilesAnchored())
        return RangeToTerrainPoint(_Range, _RangeOrigin, TileCount(), uint2(slot % across, slot / across), tess);
    int2 cell;
    bool2 whole;
    float4 span = AnchoredTileSpan(slot, cell, whole);
    float m = TileCount();
    TerrainPoint p;
    p.originHi = _RangeOrigin.xy;
    p.local = _RangeOrigin.zw + float2(AxisPoint(span.xz, whole.x, _TileLattice.x, _TileLattice.z, m, cell.x, tess.x),
                                       AxisPoint(span.yw, whole.y, _TileLattice.y, _TileLattice.w, m, cell.y, tess.y));
    return p;
}

// The terrain part (relative to the origin) slot `slot` draws, (l.x, l.y, h.x, h.y): anchored only.
float4 TileSpan(uint slot)
{
    int2 cell;
    bool2 whole;
    return AnchoredTileSpan(slot, cell, whole);
}

// An anchored tile without area (a cell past g, or the last one when the range ends on a lattice
// line): culled, so its degenerate triangles cost nothing.
bool TileEmpty(uint slot)
{
    if (!TilesAnchored()) return false;
    float4 span = TileSpan(slot);
    return span.x == span.z || span.y == span.w;
}

// --- The cells the adaptive factors are decided on -------------------------------------------------

// Lattice cell (cell.x, cell.y), relative to the origin: (l.x, l.y, h.x, h.y).
float4 LatticeCell(int2 cell)
{
    float m = TileCount();
    return float4(LatticeLine(_TileLattice.x, _TileLattice.z, m, cell.x), LatticeLine(_TileLattice.y, _TileLattice.w, m, cell.y),
                  LatticeLine(_TileLattice.x, _TileLattice.z, m, cell.x + 1), LatticeLine(_TileLattice.y, _TileLattice.w, m, cell.y + 1));
}

// The whole cell slot `slot` holds (anchored only): its tile before clipping.
float4 CellSpan(uint slot)
{
    int2 cell;
    bool2 whole;
    AnchoredTileSpan(slot, cell, whole);
    return LatticeCell(cell);
}

// The global point of tess coordinate `tess` in the whole cell slot `slot` holds: the tile's own
// point where the tile is the whole cell (the lattice formula, bit for bit), else also beyond its
// clipped side. Laid over the range, the tile's point. The adaptive factors sample the cell, not
// the clipped tile (TileFactors.hlsl), so a pan changes no cell's samples.
TerrainPoint CellToTerrainPoint(uint slot, float2 tess)
{
    if (!TilesAnchored()) return TileToTerrainPoint(slot, tess);
    int2 cell;
    bool2 whole;
    AnchoredTileSpan(slot, cell, whole);
    float m = TileCount();
    TerrainPoint p;
    p.originHi = _RangeOrigin.xy;
    p.local = _RangeOrigin.zw + float2(LatticePoint(_TileLattice.x, _TileLattice.z, m, cell.x, tess.x),
                                       LatticePoint(_TileLattice.y, _TileLattice.w, m, cell.y, tess.y));
    return p;
}

// Where x lies in the cell [lo, hi]: exactly 0 and 1 at its lines, else (x - lo) / (hi - lo).
float CellParameter(float x, float lo, float hi) { return x == lo ? 0.0 : (x == hi ? 1.0 : (x - lo) / (hi - lo)); }

// The part of its cell the tile keeps, in the cell's own parameters: (s0.x, s1.x, s0.y, s1.y),
// exactly (0, 1, 0, 1) on whole axes (and laid over the range). Tiles of one column share x, of one
// row y: tiles sharing an edge agree on its part (ClippedCell.hlsl draws it from the whole cell).
float4 TileKeptCellSpan(uint slot)
{
    if (!TilesAnchored()) return float4(0.0, 1.0, 0.0, 1.0);
    int2 cell;
    bool2 whole;
    float4 span = AnchoredTileSpan(slot, cell, whole);
    float4 c = LatticeCell(cell);
    return float4(CellParameter(span.x, c.x, c.z), CellParameter(span.z, c.x, c.z),
                  CellParameter(span.y, c.y, c.w), CellParameter(span.w, c.y, c.w));
}

// How much of its cell the tile keeps along x and y: the width of its TileKeptCellSpan, exactly 1
// on a whole axis (and laid over the range), never above 1. Tiles sharing an edge share the row or
// column that decides it. The domain-stage path scales the cell's factors by it (TileFactorsOfCell).
float2 TileKeptFraction(uint slot)
{
    float4 kept = TileKeptCellSpan(slot);
    return kept.yw - kept.xz;
}

// Edge lengths of the slot's cell along x and y in terrain units (the factors' noise term): from
// the lattice lines, so a shared edge's length is its row's or column's and both tiles see the
// same. Laid over the range: (range width) / M.
float2 CellEdgeLengths(uint slot)
{
    if (!TilesAnchored()) return (_Range.zw - _Range.xy) / TileCount();
    float4 c = CellSpan(slot);
    return c.zw - c.xy;
}

#endif // GT_TILE_LATTICE_INCLUDED
