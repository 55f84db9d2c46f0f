using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// L(x, w) of eq. 1: how exposed cell x is to the wind-driven snowfall. Mirrors Shaders/Snow/SnowExposure.hlsl.
    /// <para>
    /// A march from x upwind over the height field (snow.md, "What it computes"): each sample at
    /// horizontal distance t and height difference dz blocks the fall line (elevation F) by
    /// <c>sin(H - F) = (dz cos F - t sin F) / sqrt(t^2 + dz^2)</c> (no trigonometry, bounded in
    /// [-1, 1], and t &gt; 0 so the root is never 0); <c>L = 1 - smoothstep(0, softness, max)</c>.
    /// Without horizontal wind (F = 90 degrees) it returns 1 without marching. Samples that leave the
    /// unit square end the march: beyond the terrain is open ground. Recomputed only when the terrain
    /// or the snowfall direction changes (<see cref="SnowSimulation.NeedsExposureUpdate"/>).
    /// </para>
    /// </summary>
    internal static class SnowExposure
    {
        /// <summary>sin(H - F) of one march sample: &gt; 0 when it stands above the fall line. Needs t &gt; 0.</summary>
        public static float Occlusion(float dz, float t, float cosF, float sinF) =>
            (dz * cosF - t * sinF) / sqrt(t * t + dz * dz);

        /// <summary>L from the worst occlusion: 1 at or below the fall line, 0 at <paramref name="softness"/> above it.</summary>
        public static float FromOcclusion(float occlusion, float softness) => 1f - smoothstep(0f, softness, occlusion);

        /// <summary>
        /// Bilinear height at terrain point p, between cell centres, edge cells repeated outside.
        /// <paramref name="grid"/> is <c>_SnowGrid = (R, 1/R, rayLength, raySteps)</c>.
        /// </summary>
        public static float SampleHeight(float[] field, Float4 grid, Float2 p)
        {
            SnowCellBlend b = SnowCells.Bilinear(grid.x, p);
            return SnowCells.Blend(b, field[4 * b.c00 + 3], field[4 * b.c10 + 3], field[4 * b.c01 + 3], field[4 * b.c11 + 3]);
        }

        /// <summary>
        /// L at cell (i, j). <paramref name="fall"/> is <c>_SnowFall = (upwind.xy, cos F, sin F)</c>
        /// (<see cref="SnowSettings.FallLine"/>), <paramref name="softness"/> the exposure softness.
        /// </summary>
        public static float Evaluate(float[] field, int i, int j, Float4 grid, Float4 fall, float softness)
        {
            if (!(fall.z > 0f)) return 1f;  // no horizontal wind: snow falls straight, nothing shields
            int r = (int)grid.x;
            Float2 x = new Float2((i + 0.5f) * grid.y, (j + 0.5f) * grid.y);
            float h0 = field[4 * (j * r + i) + 3];
            int steps = (int)grid.w;
            float stepLength = grid.z / grid.w;
            float occlusion = -1f;
            for (int k = 1; k <= steps; k++)
            {
                float t = k * stepLength;
                Float2 p = new Float2(x.x + fall.x * t, x.y + fall.y * t);
                if (p.x < 0f || p.x > 1f || p.y < 0f || p.y > 1f) break;
                float dz = SampleHeight(field, grid, p) - h0;
                occlusion = Math.Max(occlusion, Occlusion(dz, t, fall.z, fall.w));
            }
            return FromOcclusion(occlusion, softness);
        }

        /// <summary>HLSL's smoothstep: 0 below a, 1 above b, 3t^2 - 2t^3 between.</summary>
        internal static float smoothstep(float a, float b, float x)
        {
            float t = saturate((x - a) / (b - a));
            return t * t * (3f - 2f * t);
        }
    }
}
