using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A tile's factors as the hull stage decides them (frustum culling, then the chord error of its
    /// edges, midlines and diagonals in pixels), on Core's float path: the triangle estimate's
    /// (<see cref="TerrainTriangleEstimate"/>). Mirrors <c>Shaders/Terrain/TileFactors.hlsl</c> name for
    /// name. Samples are of the tile's cell; a clipped tile draws its cell's factors scaled to the part it keeps.
    /// </summary>
    internal static class TileFactors
    {
        /// <summary>Pieces: the edges u = 0, v = 0, u = 1, v = 1, the midlines along u and along v, the centre.</summary>
        public const int Pieces = 7;

        const int Segments = TessellationPolicy.EdgeSegments;

        /// <summary>Corner c sits at tess coordinate (c &amp; 1, c &gt;&gt; 1).</summary>
        public static Float2 CornerTessCoordinate(int corner) => new Float2(corner & 1, corner >> 1);

        /// <summary>Object position of corner c of the tile's cell (no noise): the culling box and the edges' ends.</summary>
        public static Float3 CellCornerObjectPosition(TerrainInputs inputs, int tile, int corner)
        {
            TerrainSurfacePoint s = TerrainVertex.EvaluateCellSurface(inputs, tile, CornerTessCoordinate(corner));
            return TerrainVertex.TerrainToObject(TerrainVertex.OutputSurfacePosition(inputs, s, TerrainKeywords.None));
        }

        /// <summary>
        /// Object position of the Gregory surface (no noise) at a tess coordinate of the tile's cell, in
        /// the frame the vertices output (relative to S(O) while a range origin is set), as the corners.
        /// </summary>
        public static Float3 CellSurfaceObjectPosition(TerrainInputs inputs, int tile, Float2 tess) =>
            TerrainVertex.TerrainToObject(TerrainVertex.OutputSurfacePosition(inputs, TerrainVertex.EvaluateCellSurface(inputs, tile, tess), TerrainKeywords.None));

        /// <summary>HLSL <c>ObjectPixelsPerUnit</c>: pixels per object unit at p (TessellationPolicy.PixelsPerUnit).</summary>
        public static float ObjectPixelsPerUnit(Float4x4 objectToClip, Float3 p, Float2 screenSize) =>
            TessellationPolicy.PixelsPerUnit(objectToClip, p, screenSize);

        /// <summary>HLSL <c>UniformTileFactors</c>: every factor the uniform one, when the inputs set one (true, f set).</summary>
        public static bool UniformTileFactors(TerrainInputs inputs, out TileFactorSet f)
        {
            float u = inputs.UniformTessFactor();
            f = new TileFactorSet(new Float4(u, u, u, u), new Float2(u, u));
            return inputs.UsesUniformTessFactor();
        }

        /// <summary>HLSL <c>CulledTileFactors</c>: all zero, the patch is dropped.</summary>
        public static TileFactorSet CulledTileFactors() => default;

        /// <summary>
        /// HLSL <c>TileNoiseMargin</c>: how far the noise may move the tile's surface: with a range origin O
        /// (not paper mode) <see cref="TessellationPolicy.NoiseDifferenceBound"/> at the cell corners' largest
        /// distance from O, else <see cref="TessellationPolicy.NoiseHeightBound"/>; 0 without noise.
        /// </summary>
        public static float TileNoiseMargin(TerrainInputs inputs, int tile, TerrainKeywords keywords)
        {
            if ((keywords & TerrainKeywords.Noise) == 0) return 0f;
            Float4 originF = inputs.Params.rangeOrigin;
            if ((keywords & TerrainKeywords.PaperMode) == 0 && RelativeSurface.IsActive(originF))
            {
                TerrainPoint origin = RelativeSurface.OriginPoint(originF);
                float d = 0f;
                for (int c = 0; c < 4; c++)
                {
                    Float2 t = CornerTessCoordinate(c);
                    Float2 diff = RelativeSurface.Difference(TileLattice.CellToTerrainPoint(inputs.Params, tile, t.x, t.y), origin);
                    d = Math.Max(d, (float)Math.Sqrt(diff.x * diff.x + diff.y * diff.y));
                }
                return TessellationPolicy.NoiseDifferenceBound(inputs.NoiseSettingsStruct(), inputs.MaxNoiseOctaves(), d);
            }
            return TessellationPolicy.NoiseHeightBound(inputs.NoiseSettingsStruct());
        }

        /// <summary>
        /// HLSL <c>TileCulled</c>: the corners' box of slot <paramref name="tile"/>'s cell, grown in
        /// height by their spread plus the noise margin (<see cref="TileNoiseMargin"/>), and upwards by
        /// the snow cap (<see cref="TerrainKeywords.Snow"/>: snow only raises the surface), lies outside the view.
        /// </summary>
        public static bool TileCulled(TerrainInputs inputs, int tile, Float4x4 objectToClip, Float3[] cornersOS, TerrainKeywords keywords)
        {
            float noise = TileNoiseMargin(inputs, tile, keywords);
            float snow = (keywords & TerrainKeywords.Snow) != 0 ? inputs.SnowDepthCap() : 0f;
            return TessellationPolicy.TileCulled(objectToClip, cornersOS, noise, snow);
        }

        /// <summary>
        /// HLSL <c>TileFactorLine</c>: piece 0-5 runs from tess coordinate a to b (a the lower one);
        /// an edge's ends are corners, a midline's are surface points; axis 0 runs along u, 1 along v.
        /// </summary>
        public static void TileFactorLine(int piece, out Float2 a, out Float2 b, out int cornerA, out int cornerB, out int axis)
        {
            switch (piece)
            {
                case 0: a = new Float2(0f, 0f); b = new Float2(0f, 1f); cornerA = 0; cornerB = 2; axis = 1; return;
                case 1: a = new Float2(0f, 0f); b = new Float2(1f, 0f); cornerA = 0; cornerB = 1; axis = 0; return;
                case 2: a = new Float2(1f, 0f); b = new Float2(1f, 1f); cornerA = 1; cornerB = 3; axis = 1; return;
                case 3: a = new Float2(0f, 1f); b = new Float2(1f, 1f); cornerA = 2; cornerB = 3; axis = 0; return;
                case 4: a = new Float2(0f, 0.5f); b = new Float2(1f, 0.5f); cornerA = cornerB = -1; axis = 0; return;
                case 5: a = new Float2(0.5f, 0f); b = new Float2(0.5f, 1f); cornerA = cornerB = -1; axis = 1; return;
                default: throw new ArgumentOutOfRangeException(nameof(piece), piece, "a line piece is 0-5");
            }
        }

        /// <summary>HLSL <c>TileLineInnerPosition</c>: inner point i (1 .. n - 1) of the tile's line from a to b.</summary>
        public static Float3 TileLineInnerPosition(TerrainInputs inputs, int tile, Float2 a, Float2 b, int i) =>
            // lerp(a, b, i / n) in float, as the shader forms the sample's tess coordinate.
            CellSurfaceObjectPosition(inputs, tile, a + (b - a) * ((float)i / Segments));

        /// <summary>HLSL <c>TileCentrePosition</c>.</summary>
        public static Float3 TileCentrePosition(TerrainInputs inputs, int tile) => CellSurfaceObjectPosition(inputs, tile, new Float2(0.5f, 0.5f));

        /// <summary>HLSL <c>TileLineInnerSample</c>: the inner point and its pixels per object unit (w).</summary>
        public static Float4 TileLineInnerSample(TerrainInputs inputs, int tile, Float2 a, Float2 b, int i, Float4x4 objectToClip, Float2 screenSize)
        {
            Float3 p = TileLineInnerPosition(inputs, tile, a, b, i);
            return new Float4(p, ObjectPixelsPerUnit(objectToClip, p, screenSize));
        }

        /// <summary>HLSL <c>TileCentreSample</c>.</summary>
        public static Float4 TileCentreSample(TerrainInputs inputs, int tile, Float4x4 objectToClip, Float2 screenSize)
        {
            Float3 centre = TileCentrePosition(inputs, tile);
            return new Float4(centre, ObjectPixelsPerUnit(objectToClip, centre, screenSize));
        }

        /// <summary>
        /// HLSL <c>LineErrorTessFactor</c>: the factor whose chord error is the target, from the
        /// line's <see cref="TessellationPolicy.EdgeSegments"/> + 1 points and their pixel scales
        /// (0 at the ends), plus the bound of the noise the frame draws.
        /// </summary>
        public static float LineErrorTessFactor(TerrainInputs inputs, int tile, int piece, Float3[] p, float[] k, TerrainKeywords keywords)
        {
            float kMax = 0f;
            for (int i = 1; i < Segments; i++) kMax = Math.Max(kMax, k[i]);
            TileFactorLine(piece, out _, out _, out _, out _, out int axis);
            Float2 edgeLengths = TileLattice.CellEdgeLengths(inputs.Params, tile);
            float edgeLength = axis == 0 ? edgeLengths.x : edgeLengths.y;
            float noiseCurvature = 0f;
            if ((keywords & TerrainKeywords.Noise) != 0)
                noiseCurvature = TessellationPolicy.NoiseCurvatureBound(inputs.NoiseSettingsStruct(), LineOctaveCount(inputs, kMax));
            float sagitta = TessellationPolicy.EdgeSagittaPixels(p, k) + TessellationPolicy.NoiseSagittaPixels(noiseCurvature, edgeLength, kMax);
            return TessellationPolicy.ErrorTessFactor(sagitta, inputs.TargetPixelsPerSegment(), inputs.MaxTessFactor());
        }

        /// <summary>
        /// HLSL <c>LineOctaveCount</c>: the octaves the noise bound of a line counts. The frame's one
        /// count, or under the continuous rule (<see cref="TerrainInputs.NoiseSegmentPixels"/> &gt; 0)
        /// the count at the line's largest pixel scale: its nearest sample draws the most octaves.
        /// </summary>
        public static float LineOctaveCount(TerrainInputs inputs, float maxPixelsPerUnit) =>
            inputs.NoiseSegmentPixels() > 0f ? TerrainInputs.NoiseOctaveCountAt(inputs.Params, maxPixelsPerUnit) : inputs.NoiseOctaveCount();

        /// <summary>HLSL <c>CentreErrorTessFactor</c>: piece 6, the centre's deviation from the diagonals (centre.w: its pixel scale).</summary>
        public static float CentreErrorTessFactor(TerrainInputs inputs, Float3[] cornersOS, Float4 centre) =>
            TessellationPolicy.InsideErrorTessFactor(
                TessellationPolicy.DiagonalSagittaPixels(cornersOS[0], cornersOS[1], cornersOS[2], cornersOS[3], centre.xyz, centre.w),
                inputs.TargetPixelsPerSegment(), inputs.MaxTessFactor());

        /// <summary>HLSL <c>TileFactorPiece</c>: one piece, its surface samples evaluated in turn.</summary>
        public static float TileFactorPiece(TerrainInputs inputs, int tile, int piece, Float3[] cornersOS,
                                            Float4x4 objectToClip, Float2 screenSize, TerrainKeywords keywords)
        {
            if (piece == 6) return CentreErrorTessFactor(inputs, cornersOS, TileCentreSample(inputs, tile, objectToClip, screenSize));
            TileFactorLine(piece, out Float2 a, out Float2 b, out int cornerA, out int cornerB, out _);
            var p = new Float3[Segments + 1];
            var k = new float[Segments + 1];
            p[0] = piece < 4 ? cornersOS[cornerA] : CellSurfaceObjectPosition(inputs, tile, a);
            p[Segments] = piece < 4 ? cornersOS[cornerB] : CellSurfaceObjectPosition(inputs, tile, b);
            for (int i = 1; i < Segments; i++)
            {
                Float4 v = TileLineInnerSample(inputs, tile, a, b, i, objectToClip, screenSize);
                p[i] = v.xyz;
                k[i] = v.w;
            }
            return LineErrorTessFactor(inputs, tile, piece, p, k, keywords);
        }

        /// <summary>HLSL <c>TileFactorsOfPieces</c>: the inside factors follow the edges along them, the midlines and the centre.</summary>
        public static TileFactorSet TileFactorsOfPieces(float[] piece)
        {
            Float2 inside = TessellationPolicy.InsideFactors(piece[0], piece[1], piece[2], piece[3]);
            float centre = piece[6];
            inside = new Float2(Math.Max(Math.Max(inside.x, piece[4]), centre), Math.Max(Math.Max(inside.y, piece[5]), centre));
            return new TileFactorSet(new Float4(piece[0], piece[1], piece[2], piece[3]), inside);
        }

        /// <summary>
        /// HLSL <c>TileFactorsOfCell</c>: each line's factor times the part <paramref name="kept"/> of the
        /// cell the tile keeps along it, at least 1 (segments no longer than the cell's). Whole: bit for bit.
        /// </summary>
        public static TileFactorSet TileFactorsOfCell(TileFactorSet cell, Float2 kept)
        {
            if (cell.IsCulled) return cell;
            Float4 edge = cell.edge;
            return new TileFactorSet(
                new Float4(Math.Max(edge.x * kept.y, 1f), Math.Max(edge.y * kept.x, 1f), Math.Max(edge.z * kept.y, 1f), Math.Max(edge.w * kept.x, 1f)),
                new Float2(Math.Max(cell.inside.x * kept.x, 1f), Math.Max(cell.inside.y * kept.y, 1f)));
        }

        /// <summary>Tile factors exist in tile mode only (paper mode has no hull_const factors).</summary>
        static void RequireTileMode(TerrainInputs inputs, TerrainKeywords keywords)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            if ((keywords & TerrainKeywords.PaperMode) != 0)
                throw new ArgumentException("keywords: tile factors are the tile mode's (paper mode has no hull_const factors)", nameof(keywords));
        }

        /// <summary>
        /// HLSL <c>ComputeTileFactors</c> (hull_const's path): the uniform factor when one is set;
        /// else all zero for a culled tile; else the seven pieces. <paramref name="objectToClip"/>:
        /// the camera's <c>GT_ObjectToClip</c>; <paramref name="screenSize"/> in pixels.
        /// <see cref="TerrainKeywords.Noise"/> adds the noise bound, <see cref="TerrainKeywords.Snow"/>
        /// the snow cap to the culling box (its inputs then need a snow map).
        /// </summary>
        public static TileFactorSet ComputeTileFactors(TerrainInputs inputs, int tile, Float4x4 objectToClip, Float2 screenSize,
                                                       TerrainKeywords keywords)
        {
            RequireTileMode(inputs, keywords);
            if (TileLattice.TileEmpty(inputs.Params, tile)) return CulledTileFactors();
            if (UniformTileFactors(inputs, out TileFactorSet f)) return f;
            return TileFactorsOfCell(ComputeCellFactors(inputs, tile, objectToClip, screenSize, keywords), TileLattice.TileKeptFraction(inputs.Params, tile));
        }

        /// <summary>
        /// The float factors of slot <paramref name="tile"/>'s whole cell (the tile itself unless
        /// anchored and clipped): culled by the cell's corners, else the seven pieces of its samples.
        /// What the vertex cache's kernel decides for a tile with adaptive factors (before rounding).
        /// </summary>
        public static TileFactorSet ComputeCellFactors(TerrainInputs inputs, int tile, Float4x4 objectToClip, Float2 screenSize,
                                                       TerrainKeywords keywords)
        {
            if (inputs == null) throw new ArgumentNullException(nameof(inputs));
            var corners = new Float3[4];
            for (int c = 0; c < 4; c++) corners[c] = CellCornerObjectPosition(inputs, tile, c);
            if (TileCulled(inputs, tile, objectToClip, corners, keywords)) return CulledTileFactors();
            var piece = new float[Pieces];
            for (int i = 0; i < Pieces; i++) piece[i] = TileFactorPiece(inputs, tile, i, corners, objectToClip, screenSize, keywords);
            return TileFactorsOfPieces(piece);
        }

        /// <summary>
        /// What the vertex cache's draw gives slot <paramref name="tile"/>: its cell's factors rounded
        /// as the kernel rounds them (<see cref="VertexCache.IntegerFactors"/>; the uniform factor when
        /// one is set), clipped to the part of the cell the tile keeps as the hull clips them
        /// (<see cref="ClippedCell.ClippedTileFactors"/>).
        /// </summary>
        public static TileFactorSet ComputeCachedTileFactors(TerrainInputs inputs, int tile, Float4x4 objectToClip, Float2 screenSize,
                                                             TerrainKeywords keywords)
        {
            RequireTileMode(inputs, keywords);
            TileFactorSet cell = UniformTileFactors(inputs, out TileFactorSet f) ? f : ComputeCellFactors(inputs, tile, objectToClip, screenSize, keywords);
            return ClippedCell.ClippedTileFactors(VertexCache.IntegerFactors(cell), TileLattice.TileKeptCellSpan(inputs.Params, tile));
        }
    }
}
