using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The deep-zoom vertex position: the surface point relative to the surface at the range origin,
    /// <c>S(q) - S(O)</c>, from precise local differences instead of two absolute floats (precision.md,
    /// "What the shaders do"). The shaders output it as the object position whenever <c>_RangeOrigin</c>
    /// is not zero; the renderer adds <see cref="ReferencePoint"/> (double) in the object-to-world
    /// transform. Mirrors Shaders/Library/RelativeSurface.hlsl (float path);
    /// <see cref="FromOrigin(PatchGrid, Double2, Double2)"/> is the double reference.
    /// <para>How: with q in patch p, r1 = O clamped into p's region and p0 = O's patch,
    /// <c>S(q) - S(O) = [S_p(q) - S_p(r1)] + [S_p0(r1) - S_p0(O)]</c>, each bracket a
    /// <see cref="GregoryDifference"/> within one patch; r1 lies on the boundary p and p0 share, where
    /// they agree bit for bit. A q farther away walks patch by patch to O. Everything depends only on
    /// q and per-frame constants, so shared tile edges stay bit-identical.</para>
    /// </summary>
    internal static class RelativeSurface
    {
        /// <summary>
        /// <c>p - r</c> per axis for two hi/lo points, precise to float's relative precision of the
        /// result: the large parts' difference is taken exactly (TwoSum), the small parts added to it.
        /// </summary>
        public static Float2 Difference(TerrainPoint p, TerrainPoint r)
        {
            float sx = RangeMapping.TwoSum(p.originHi.x, -r.originHi.x, out float ex);
            float sy = RangeMapping.TwoSum(p.originHi.y, -r.originHi.y, out float ey);
            return new Float2(sx + (ex + (p.local.x - r.local.x)), sy + (ey + (p.local.y - r.local.y)));
        }

        /// <summary>The range origin as a <see cref="TerrainPoint"/>: (hi, lo) of <c>_RangeOrigin</c>.</summary>
        public static TerrainPoint OriginPoint(Float4 rangeOriginF) =>
            new TerrainPoint(new Float2(rangeOriginF.x, rangeOriginF.y), new Float2(rangeOriginF.z, rangeOriginF.w));

        /// <summary>True when the shaders use the relative output: <c>_RangeOrigin</c> is not all zero.</summary>
        public static bool IsActive(Float4 rangeOriginF) =>
            rangeOriginF.x != 0f || rangeOriginF.y != 0f || rangeOriginF.z != 0f || rangeOriginF.w != 0f;

        /// <summary>
        /// Whether a tessellated draw needs the <c>GT_RANGE_ORIGIN</c> keyword: while the origin is set
        /// (<see cref="IsActive"/>), except under <c>GT_LOD</c> or <c>GT_VERTEX_CACHE</c>, which compile the
        /// same code (one keyword set, at most one on). Without any of them a set origin is drawn wrong.
        /// </summary>
        public static bool NeedsRangeOriginKeyword(Float4 rangeOriginF, bool levels, bool cache) => !levels && !cache && IsActive(rangeOriginF);

        /// <summary>
        /// The patch that holds the hi/lo point <paramref name="q"/> by the FindPatch rule, decided on the
        /// precise point against the hi/lo <c>_GridLines</c>: FindPatch on the rounded <c>hi + local</c> can
        /// be one patch off within a float step of a line, clamping u or v into a flat strip. One step to
        /// the neighbour fixes it. Used by the tile path while a range origin is set (<see cref="FindPatchAt"/>).
        /// </summary>
        public static int FindPatchPrecise(TerrainInputs grid, TerrainPoint q)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            return FindPatchCorrect(grid, q, grid.FindPatch(RangeMapping.Approximate(q)));
        }

        /// <summary>
        /// HLSL <c>FindPatchCorrect</c>: <see cref="FindPatchPrecise"/>'s step from <paramref name="patch"/>,
        /// FindPatch's answer on the rounded point, to the precise point's patch.
        /// </summary>
        public static int FindPatchCorrect(TerrainInputs grid, TerrainPoint q, int patch)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            int i = patch % grid.GridColumns(), j = patch / grid.GridColumns();
            Float4 region = grid.PatchRegion(patch), regionLo = grid.PatchRegionLo(patch);
            Float2 lo = Difference(q, new TerrainPoint(region.xy, regionLo.xy));
            Float2 hi = Difference(q, new TerrainPoint(new Float2(region.z, region.w), new Float2(regionLo.z, regionLo.w)));
            if (lo.x < 0f && i > 0) i--;
            else if (hi.x >= 0f && i < grid.GridColumns() - 1) i++;
            if (lo.y < 0f && j > 0) j--;
            else if (hi.y >= 0f && j < grid.GridRows() - 1) j++;
            return j * grid.GridColumns() + i;
        }

        /// <summary>
        /// The tile path's lookup (HLSL <c>FindPatchAt</c>): <see cref="FindPatchPrecise"/> while
        /// <paramref name="q"/> has a hi part (a range origin is set), else FindPatch on the plain float
        /// point, where the patches meet within a rounding and the correction would cost domain-stage time.
        /// </summary>
        public static int FindPatchAt(TerrainInputs grid, TerrainPoint q)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            int patch = grid.FindPatch(RangeMapping.Approximate(q));
            if (q.originHi.x != 0f || q.originHi.y != 0f)
                patch = FindPatchCorrect(grid, q, patch);
            return patch;
        }

        /// <summary>
        /// <paramref name="p"/> clamped into the hi/lo region (a, b, e, f) per axis (a region bound is
        /// the point (hi, lo)). Returns p itself, bit for bit, when it is inside.
        /// </summary>
        public static TerrainPoint ClampToRegion(TerrainPoint p, Float4 region, Float4 regionLo)
        {
            Float2 lo = Difference(p, new TerrainPoint(region.xy, regionLo.xy));
            Float2 hi = Difference(p, new TerrainPoint(new Float2(region.z, region.w), new Float2(regionLo.z, regionLo.w)));
            TerrainPoint r = p;
            if (lo.x < 0f) { r.originHi.x = region.x; r.local.x = regionLo.x; }
            else if (hi.x > 0f) { r.originHi.x = region.z; r.local.x = regionLo.z; }
            if (lo.y < 0f) { r.originHi.y = region.y; r.local.y = regionLo.y; }
            else if (hi.y > 0f) { r.originHi.y = region.w; r.local.y = regionLo.w; }
            return r;
        }

        /// <summary>
        /// <c>S_p(x) - S_p(r)</c> in one patch: u0 = local coordinate of r, (du, dv) = (x - r) / region size,
        /// u0 clamped to [0, 1]; the region as hi/lo pairs. <paramref name="cp"/> may be relative to any
        /// point (a difference does not see it).
        /// </summary>
        public static Float3 PatchDifference(ReadOnlySpan<Float3> cp, Float4 region, Float4 regionLo, TerrainPoint x, TerrainPoint r)
        {
            Float2 uv0 = RangeMapping.PatchLocalUV(r, region, regionLo);
            float u0 = GMath.saturate(uv0.x), v0 = GMath.saturate(uv0.y);
            Float2 d = Difference(x, r);
            Float2 size = RangeMapping.RegionSize(region, regionLo);
            float du = d.x / size.x, dv = d.y / size.y;
            // Not clamped to u0 + du in [0, 1]: u0 is rounded, and clamping against it would freeze
            // vertices near a patch edge; the pair guard keeps the rounding overshoot finite.
            du = GMath.clamp(du, -1f, 1f);
            dv = GMath.clamp(dv, -1f, 1f);
            return GregoryDifference.Evaluate(cp, u0, v0, du, dv);
        }

        /// <summary>
        /// <c>S(q) - S(O)</c> in float, as the shaders compute it (HLSL <c>RelativeSurfaceFromOrigin</c>).
        /// <paramref name="q"/>: the vertex's global point (RangeMapping.ToTerrainPoint).
        /// </summary>
        public static Float3 FromOrigin(TerrainInputs grid, TerrainPoint q, Float4 rangeOriginF)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            Span<Float3> cp = stackalloc Float3[GregoryPatch.SlotCount];
            TerrainPoint origin = OriginPoint(rangeOriginF);
            int n = grid.GridColumns();
            int patch = FindPatchPrecise(grid, q);
            int i = patch % n, j = patch / n;
            TerrainPoint from = q;   // the first step starts at q itself (outside [0, 1] the difference extrapolates)
            Float3 d = default;
            for (int k = 0; k <= n + grid.GridRows(); k++)
            {
                int p = j * n + i;
                Float4 region = grid.PatchRegion(p), regionLo = grid.PatchRegionLo(p);
                TerrainPoint to = ClampToRegion(origin, region, regionLo);
                grid.LoadGregoryPatch(p, cp);
                d += PatchDifference(cp, region, regionLo, from, to);
                Float2 toward = Difference(origin, to);   // 0 on an axis where O is inside p
                int si = Math.Sign(toward.x), sj = Math.Sign(toward.y);
                if (si == 0 && sj == 0) break;
                i += si;
                j += sj;
                from = to;   // on the line or corner the next patch shares: inside it, bit for bit
            }
            return d;
        }

        /// <summary>The double reference: <c>S(q) - S(O)</c> from two double evaluations (error ~1e-17).</summary>
        public static Double3 FromOrigin(PatchGrid grid, Double2 q, Double2 origin) =>
            SurfaceAt(grid, q) - SurfaceAt(grid, origin);

        /// <summary>
        /// <c>S(O)</c> in double for the origin the GPU holds: what the renderer adds back in the
        /// object-to-world transform while the relative output is active.
        /// </summary>
        public static Double3 ReferencePoint(PatchGrid grid, RangeOrigin origin) => SurfaceAt(grid, origin.Value);

        /// <summary>The surface point S(q) in double: the patch holding q, the corrected eq. 10, evaluation.</summary>
        public static Double3 SurfaceAt(PatchGrid grid, Double2 q)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            if (!q.IsFinite) throw new ArgumentException(FormattableString.Invariant($"q {q} must be finite"), nameof(q));
            int p = grid.FindPatch(q.x, q.y);
            Double2 uv = RangeMapping.LocalCoordinate(q, grid.RegionOf(p));
            return GregoryEval.Position(grid.Patches[p].Points, uv.x, uv.y);
        }
    }
}
