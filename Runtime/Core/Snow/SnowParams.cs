using System;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// The <c>SnowParams</c> constants of the snow simulation's kernels (internals.md, "Snow"): five
    /// float4, 80 bytes, declared here once. <c>gt generate</c> writes the HLSL members
    /// (Shaders/Snow/SnowParams.cs.hlsl, inside SnowSimulation.compute's cbuffer) and
    /// SnowParams.Generated.cs (<see cref="PropertyNames"/>, <see cref="Float4Count"/>) from these
    /// fields, in their order. Made by <see cref="SnowSettings.Params"/>; the rig uploads
    /// <see cref="Pack"/> as one block, Unity sets each float4 by name.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Snow/SnowParams.cs.hlsl", "Runtime/Core/Snow/SnowParams.Generated.cs")]
    internal partial struct SnowParams : IFloat4Block
    {
        // Instance fields only below, in cbuffer order: the layout is the declaration order.
        [HlslComment("(R, 1/R, rayLength, raySteps)")]
        public Float4 snowGrid;
        [HlslComment("(upwind.xy, cos F, sin F): SnowSettings.FallLine")]
        public Float4 snowFall;
        [HlslComment("(Gn.xyz, scale s)")]
        public Float4 snowCatch;
        [HlslComment("(edgeStrength, edgeWidth, exposureSoftness, 0)")]
        public Float4 snowEdge;
        [HlslComment("(dt, depthCap, meltRate, 0)")]
        public Float4 snowStep;

        /// <summary>Seconds of this step.</summary>
        public float Dt => snowStep.x;
        /// <summary>Largest snow depth.</summary>
        public float DepthCap => snowStep.y;
        /// <summary>Depth melted per second.</summary>
        public float MeltRate => snowStep.z;
        /// <summary>How softly a cell's exposure falls off (SnowExposure.Evaluate).</summary>
        public float ExposureSoftness => snowEdge.z;

        /// <summary>The float4 at cbuffer position <paramref name="index"/> (see <see cref="PropertyNames"/>).</summary>
        public Float4 this[int index] => Float4Block.At(ref this, index, Float4Count);

        /// <summary>The 20 floats of the cbuffer, in order: the struct's own bytes.</summary>
        public float[] Pack() => Float4Block.Pack(this);
    }
}
