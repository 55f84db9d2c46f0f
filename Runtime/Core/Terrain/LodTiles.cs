using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Drawing the levels of detail (internals.md, "Levels of detail"): draw patch <c>p</c> is tile
    /// <c>p mod M^2</c> of level <c>p / M^2</c>, the tiles inside the finer level culled, and the seam
    /// rule that makes a coarse edge and the two fine edges along it share their vertices bit for bit.
    /// Mirrors Shaders/Terrain/LodTiles.hlsl, same names.
    /// </summary>
    internal static class LodTiles
    {
        /// <summary>Most levels a draw holds (the <c>_Ranges</c> array's length): 2^-19 of the terrain at the feet.</summary>
        public const int MaxLevels = 20;

        /// <summary>Edge bits in the tessellator's order: u = 0 (x low), v = 0 (y low), u = 1 (x high), v = 1 (y high).</summary>
        public const int EdgeU0 = 1, EdgeV0 = 2, EdgeU1 = 4, EdgeV1 = 8;

        /// <summary>Tiles a level draws: M x M on its range.</summary>
        public static int TilesPerLevel(int tiles) => tiles * tiles;

        /// <summary>The level draw patch <paramref name="drawPatch"/> belongs to. HLSL <c>LodLevelOfPatch</c>.</summary>
        public static int LevelOfPatch(int drawPatch, int tiles) => drawPatch / TilesPerLevel(tiles);

        /// <summary>The tile (slot) of its level draw patch <paramref name="drawPatch"/> is. HLSL <c>LodSlotOfPatch</c>.</summary>
        public static int SlotOfPatch(int drawPatch, int tiles) => drawPatch % TilesPerLevel(tiles);

        /// <summary>The finer range's corner in the coarser range's cells (an integer by the layout's snapping, rounded). HLSL <c>FinerOffsetCells</c>.</summary>
        public static void FinerOffsetCells(Float4 coarse, Float4 finer, float tiles, out int a, out int b)
        {
            a = (int)Math.Round((finer.x - coarse.x) / (coarse.z - coarse.x) * tiles, MidpointRounding.AwayFromZero);
            b = (int)Math.Round((finer.y - coarse.y) / (coarse.w - coarse.y) * tiles, MidpointRounding.AwayFromZero);
        }

        /// <summary>Whether coarse tile (ti, tj) lies wholly inside the finer level at offset (a, b): culled. HLSL <c>TileInsideFiner</c>.</summary>
        public static bool TileInsideFiner(int ti, int tj, int a, int b, int tiles)
        {
            int h = tiles / 2;
            return ti >= a && ti < a + h && tj >= b && tj < b + h;
        }

        /// <summary>
        /// The edges of coarse tile (ti, tj) that border the finer level at offset (a, b) (the hole's
        /// rim), as <see cref="EdgeU0"/>.. bits. HLSL <c>CoarseSeamEdges</c>.
        /// </summary>
        public static int CoarseSeamEdges(int ti, int tj, int a, int b, int tiles)
        {
            int h = tiles / 2;
            bool alongY = tj >= b && tj < b + h, alongX = ti >= a && ti < a + h;
            int mask = 0;
            if (alongY && ti == a + h) mask |= EdgeU0;
            if (alongX && tj == b + h) mask |= EdgeV0;
            if (alongY && ti == a - 1) mask |= EdgeU1;
            if (alongX && tj == b - 1) mask |= EdgeV1;
            return mask;
        }

        /// <summary>
        /// The edges of fine tile (ti, tj) on its range's boundary where the coarser level lies beyond
        /// (the level sits at offset (a, b) in the coarser one's cells; at the terrain's edge the two
        /// share the boundary and nothing lies beyond). HLSL <c>FineSeamEdges</c>.
        /// </summary>
        public static int FineSeamEdges(int ti, int tj, int a, int b, int tiles)
        {
            int h = tiles / 2, mask = 0;
            if (ti == 0 && a > 0) mask |= EdgeU0;
            if (tj == 0 && b > 0) mask |= EdgeV0;
            if (ti == tiles - 1 && a + h < tiles) mask |= EdgeU1;
            if (tj == tiles - 1 && b + h < tiles) mask |= EdgeV1;
            return mask;
        }

        /// <summary>g = ceil(f / 2) in [1, floor(maxFactor / 2)], f the coarse edge's factor: a coarse seam edge draws 2g, each fine one g. HLSL <c>SeamHalfFactor</c>.</summary>
        public static float SeamHalfFactor(float coarseEdgeFactor, float maxFactor) =>
            GMath.clamp((float)Math.Ceiling(coarseEdgeFactor * 0.5f), 1f, (float)Math.Floor(maxFactor * 0.5f));

        /// <summary>
        /// The coarse tile's tess coordinate of seam vertex n (0 .. 2g, <paramref name="halfFactor"/> g) on
        /// <paramref name="edge"/>: <c>n / (2g)</c> along, formed alike on both sides; 0 or 1 across. HLSL <c>SeamCoarseTess</c>.
        /// </summary>
        public static Float2 SeamCoarseTess(int edge, int numerator, float halfFactor)
        {
            float along = numerator / (2f * halfFactor);
            switch (edge)
            {
                case EdgeU0: return new Float2(0f, along);
                case EdgeU1: return new Float2(1f, along);
                case EdgeV0: return new Float2(along, 0f);
                case EdgeV1: return new Float2(along, 1f);
                default: throw new ArgumentException(FormattableString.Invariant($"edge ({edge}) must be one edge bit"), nameof(edge));
            }
        }

        /// <summary>
        /// The coarse tile across fine seam edge <paramref name="edge"/> of fine tile (ti, tj) at offset
        /// (a, b), and which half of it the fine edge is (<paramref name="upperHalf"/> 0: the lower tess half, 1: the upper); the
        /// coarse tile's edge on the seam is the opposite one (fine u = 0 meets coarse u = 1).
        /// HLSL <c>FineSeamCoarseTile</c>.
        /// </summary>
        public static void FineSeamCoarseTile(int edge, int ti, int tj, int a, int b, out int cti, out int ctj, out int coarseEdge, out int upperHalf)
        {
            int fx = 2 * a + ti, fy = 2 * b + tj;   // the fine tile in fine cells of the coarse range
            switch (edge)
            {
                case EdgeU0: cti = a - 1; ctj = fy / 2; upperHalf = fy % 2; coarseEdge = EdgeU1; break;
                case EdgeU1: cti = (fx + 1) / 2; ctj = fy / 2; upperHalf = fy % 2; coarseEdge = EdgeU0; break;
                case EdgeV0: cti = fx / 2; ctj = b - 1; upperHalf = fx % 2; coarseEdge = EdgeV1; break;
                case EdgeV1: cti = fx / 2; ctj = (fy + 1) / 2; upperHalf = fx % 2; coarseEdge = EdgeV0; break;
                default: throw new ArgumentException(FormattableString.Invariant($"edge ({edge}) must be one edge bit"), nameof(edge));
            }
        }

        /// <summary>The first seam edge (in edge order) a vertex at <paramref name="tess"/> lies on, or 0. HLSL <c>SeamEdgeAt</c>.</summary>
        public static int SeamEdgeAt(int mask, Float2 tess)
        {
            if ((mask & EdgeU0) != 0 && tess.x == 0f) return EdgeU0;
            if ((mask & EdgeV0) != 0 && tess.y == 0f) return EdgeV0;
            if ((mask & EdgeU1) != 0 && tess.x == 1f) return EdgeU1;
            if ((mask & EdgeV1) != 0 && tess.y == 1f) return EdgeV1;
            return 0;
        }

        /// <summary>The tess coordinate along edge <paramref name="edge"/> (v on u-edges, u on v-edges).</summary>
        public static float SeamAlong(int edge, Float2 tess) => (edge & (EdgeU0 | EdgeU1)) != 0 ? tess.y : tess.x;

        /// <summary>
        /// The global point of a seam vertex at tess <paramref name="tess"/> of tile (ti, tj) of level
        /// <paramref name="range"/>. Coarse side (<paramref name="fine"/> false): the edge's factor is
        /// <c>2g</c>, n = round(along 2g). Fine side: factor g, n = round(along g) + upperHalf g on the coarse
        /// tile across (<paramref name="coarser"/>, the level sits at (a, b) in its cells). Both form
        /// <see cref="RangeMapping.ToTerrainPoint"/> of the coarse range, tile and <see cref="SeamCoarseTess"/>.
        /// HLSL <c>SeamCoarsePoint</c>.
        /// </summary>
        public static TerrainPoint SeamCoarsePoint(bool fine, int edge, Float2 tess, float halfFactor, int ti, int tj, Float4 range,
                                                   Float4 coarser, int a, int b, Float4 rangeOrigin, int tiles)
        {
            float along = SeamAlong(edge, tess);
            if (!fine)
            {
                int n = (int)Math.Round(along * 2f * halfFactor, MidpointRounding.AwayFromZero);
                return RangeMapping.ToTerrainPoint(range, rangeOrigin, tiles, ti, tj, SeamCoarseTess(edge, n, halfFactor).x, SeamCoarseTess(edge, n, halfFactor).y);
            }
            FineSeamCoarseTile(edge, ti, tj, a, b, out int cti, out int ctj, out int coarseEdge, out int upperHalf);
            int m = (int)Math.Round(along * halfFactor, MidpointRounding.AwayFromZero) + upperHalf * (int)halfFactor;
            Float2 ct = SeamCoarseTess(coarseEdge, m, halfFactor);
            return RangeMapping.ToTerrainPoint(coarser, rangeOrigin, tiles, cti, ctj, ct.x, ct.y);
        }
    }
}
