using System;
using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// The snow depth map as the terrain stages read it (keyword <c>GT_SNOW</c>): the simulation's
    /// R x R depth per cell (<c>_SnowDepth</c>, cell (i, j) at <c>j * R + i</c>, centred on
    /// <c>((i + 0.5) / R, (j + 0.5) / R)</c>) and <c>_SnowMapSize = (R, 1/R, depthCap, 0)</c>.
    /// Mirrors <c>Shaders/Snow/SnowMap.hlsl</c> (<see cref="Sample(float[], Float4, Float2)"/> is HLSL
    /// <c>SnowMapSample</c>, <see cref="Coverage"/> is <c>SnowMapCoverage</c>).
    /// <para>
    /// The depth is sampled bilinearly between cell centres at the vertex's global point q, edge
    /// cells repeated outside the centres: a continuous function of q, so vertices shared by two tiles
    /// (bit-identical q) get identical depths and the raised surface stays watertight.
    /// </para>
    /// <para>
    /// Holds the array it is given (no copy): the simulation writes <c>Depth</c>, the terrain reads it.
    /// </para>
    /// </summary>
    internal sealed class SnowMap
    {
        /// <summary>
        /// Depth, as a fraction of the cap, at which the surface is fully white. A thin layer only
        /// tints the ground; half the cap hides it. Snow colour is a look, not a measure.
        /// </summary>
        public const float FullCoverFraction = 0.5f;

        public int Resolution { get; }
        /// <summary>Depth per cell (terrain height units), R * R floats.</summary>
        public float[] Depth { get; }
        /// <summary>Largest depth the simulation writes: the tile bounds grow by it.</summary>
        public float DepthCap { get; }

        public SnowMap(float[] depth, int resolution, float depthCap)
        {
            if (resolution < SnowSettings.MinResolution || resolution > SnowSettings.MaxResolution || (resolution & (resolution - 1)) != 0)
                throw new ArgumentException(FormattableString.Invariant($"resolution ({resolution}) must be a power of two from 64 to 4096"), nameof(resolution));
            if (depth == null) throw new ArgumentNullException(nameof(depth));
            if (depth.LongLength != (long)resolution * resolution)
                throw new ArgumentException(FormattableString.Invariant($"depth.Length ({depth.LongLength}) must be {(long)resolution * resolution} for R = {resolution}"), nameof(depth));
            if (!isfinite(depthCap) || !(depthCap > 0f))
                throw new ArgumentException(FormattableString.Invariant($"depthCap ({depthCap:R}) must be finite and > 0"), nameof(depthCap));
            Depth = depth;
            Resolution = resolution;
            DepthCap = depthCap;
        }

        /// <summary>A map over a simulation's depth array, with its settings' cap.</summary>
        public static SnowMap Of(SnowSimulation simulation)
        {
            if (simulation == null) throw new ArgumentNullException(nameof(simulation));
            return new SnowMap(simulation.Depth, simulation.Resolution, simulation.Settings.depthCap);
        }

        /// <summary><c>_SnowMapSize = (R, 1/R, depthCap, 0)</c> (1/R exact: R is a power of two).</summary>
        public Float4 MapSize => PackMapSize(Resolution, DepthCap);

        /// <summary><c>_SnowMapSize</c> for a resolution and a cap, as <c>SnowSimulator</c> sets it.</summary>
        public static Float4 PackMapSize(int resolution, float depthCap) => new Float4(resolution, 1f / resolution, depthCap, 0f);

        /// <summary>Depth at the global point <paramref name="q"/>.</summary>
        public float Sample(Float2 q) => Sample(Depth, MapSize, q);

        /// <summary>
        /// HLSL <c>SnowMapSample(depth, mapSize, q)</c>: bilinear between cell centres, edge cells
        /// repeated; <paramref name="mapSize"/> is <c>_SnowMapSize</c>.
        /// </summary>
        public static float Sample(float[] depth, Float4 mapSize, Float2 q)
        {
            SnowCellBlend b = SnowCells.Bilinear(mapSize.x, q);
            return SnowCells.Blend(b, depth[b.c00], depth[b.c10], depth[b.c01], depth[b.c11]);
        }

        /// <summary>
        /// HLSL <c>SnowMapCoverage(depth, depthCap)</c>: how white the surface is, 0 (bare) to 1
        /// (covered), a smoothstep up to <see cref="FullCoverFraction"/> of the cap.
        /// </summary>
        public static float Coverage(float depth, float depthCap) => SnowExposure.smoothstep(0f, FullCoverFraction * depthCap, depth);
    }
}
