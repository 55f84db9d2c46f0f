using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// Eq. 1's accumulation rate <c>D(x) = s L (N . Gn) max(1 - E, 0)</c> and the depth update.
    /// Mirrors Shaders/Snow/SnowAccumulation.hlsl.
    /// Each term's why: snow.md, "What it computes". The catch is saturated (an overhang gets nothing,
    /// never a negative rate that would eat snow); N is the field's detail normal, so walls catch snow.
    /// The crest sharpness <c>c = (4 h - sum of the 4 neighbours) R</c> is the drop in slope across the
    /// cell; concave cells (c &lt; 0) get E = 0.
    /// </summary>
    internal static class SnowAccumulation
    {
        /// <summary><c>saturate(dot(N, Gn))</c>: 1 facing up, 0 vertical or overhanging.</summary>
        public static float Catch(Float3 normal, Float3 up) => saturate(dot(normal, up));

        /// <summary>Crest sharpness c = (4 h - hl - hr - hd - hu) R: drop in slope across the cell; &gt; 0 on ridges.</summary>
        public static float Crest(float h, float hLeft, float hRight, float hDown, float hUp, float resolution) =>
            (4f * h - hLeft - hRight - hDown - hUp) * resolution;

        /// <summary>E = strength * smoothstep(0, width, crest).</summary>
        public static float EdgeTerm(float crest, float strength, float width) => strength * SnowExposure.smoothstep(0f, width, crest);

        /// <summary>D = s L catch max(1 - E, 0), depth per second.</summary>
        public static float Rate(float scale, float exposure, float catchTerm, float edge) =>
            scale * exposure * catchTerm * Math.Max(1f - edge, 0f);

        /// <summary>New depth after dt seconds: <c>clamp(depth + (rate - melt) dt, 0, cap)</c>.</summary>
        public static float Step(float depth, float rate, float dt, float cap, float melt) =>
            clamp(depth + (rate - melt) * dt, 0f, cap);

        /// <summary>
        /// D at cell (i, j) of the field, given its exposure. <paramref name="grid"/> = <c>_SnowGrid</c>,
        /// <paramref name="catchParams"/> = <c>_SnowCatch = (Gn.xyz, s)</c>,
        /// <paramref name="edge"/> = <c>_SnowEdge = (strength, width, softness, 0)</c>.
        /// </summary>
        public static float RateAt(float[] field, int i, int j, float exposure, Float4 grid, Float4 catchParams, Float4 edge)
        {
            int r = (int)grid.x;
            int k = 4 * (j * r + i);
            Float3 n = new Float3(field[k], field[k + 1], field[k + 2]);
            float h = field[k + 3];
            float hl = field[4 * (j * r + Math.Max(i - 1, 0)) + 3];
            float hr = field[4 * (j * r + Math.Min(i + 1, r - 1)) + 3];
            float hd = field[4 * (Math.Max(j - 1, 0) * r + i) + 3];
            float hu = field[4 * (Math.Min(j + 1, r - 1) * r + i) + 3];
            float e = EdgeTerm(Crest(h, hl, hr, hd, hu, grid.x), edge.x, edge.y);
            return Rate(catchParams.w, exposure, Catch(n, catchParams.xyz), e);
        }
    }
}
