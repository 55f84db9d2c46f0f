using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// A unit normal in two numbers for the shaders' interpolant (internals.md, "Varyings"): Lambert's
    /// azimuthal equal-area projection about +y onto the disk of radius 2. Smooth everywhere but at
    /// n = -y, so interpolating the two numbers behaves like interpolating the normal on slopes and
    /// cliffs alike. Mirrors Shaders/Library/NormalEncoding.hlsl name for name.
    /// </summary>
    internal static class NormalEncoding
    {
        /// <summary>
        /// HLSL <c>LambertEncodeNormal</c>: <c>n.xz * k</c>, k = <c>sqrt(2 / (1 + n.y))</c> in the upper
        /// half and the equal <c>sqrt(2 (1 - n.y)) / |n.xz|</c> in the lower (there the first form
        /// divides a normal's rounding by 1 + n.y). n = -y gives (0, 0).
        /// </summary>
        public static Float2 LambertEncodeNormal(Float3 n)
        {
            float k = n.y >= 0f
                ? rsqrt(0.5f + 0.5f * n.y)
                : sqrt(2f * (1f - n.y)) / System.MathF.Max(sqrt(n.x * n.x + n.z * n.z), 1e-30f);
            return new Float2(n.x * k, n.z * k);
        }

        /// <summary>
        /// HLSL <c>LambertDecodeNormal</c>: <c>(e.x sqrt(1 - f/4), 1 - f/2, e.y sqrt(1 - f/4))</c>,
        /// f = |e|^2; unit length for |e| &lt;= 2 (an interpolated e lies inside the disk).
        /// </summary>
        public static Float3 LambertDecodeNormal(Float2 e)
        {
            float f = dot(e, e);
            float s = sqrt(System.MathF.Max(1f - 0.25f * f, 0f));
            return new Float3(e.x * s, 1f - 0.5f * f, e.y * s);
        }
    }
}
