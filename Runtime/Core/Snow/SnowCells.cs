using static GregoryTerrain.GMath;

namespace GregoryTerrain
{
    /// <summary>
    /// The R x R cell grid of the snow maps (the depth map, <see cref="SnowMap"/>, and the exposure's
    /// height field, <see cref="SnowExposure"/>): cell (i, j) at <c>j * R + i</c>, centred on
    /// <c>((i + 0.5) / R, (j + 0.5) / R)</c>. Mirrors <c>Shaders/Snow/SnowCells.hlsl</c>.
    /// </summary>
    internal static class SnowCells
    {
        /// <summary>
        /// HLSL <c>SnowCellsBilinear(r, q)</c>: the four cells and the fractions of a bilinear read at
        /// <paramref name="q"/> between cell centres, edge cells repeated, in the shader's float steps:
        /// <c>q R - 0.5</c>, floor, clamp.
        /// </summary>
        public static SnowCellBlend Bilinear(float r, Float2 q)
        {
            int n = (int)r;
            float u = q.x * r - 0.5f, v = q.y * r - 0.5f;
            float fu = floor(u), fv = floor(v);
            int i0 = Clamp((int)fu, n), i1 = Clamp((int)fu + 1, n);
            int j0 = Clamp((int)fv, n), j1 = Clamp((int)fv + 1, n);
            return new SnowCellBlend
            {
                c00 = j0 * n + i0, c10 = j0 * n + i1, c01 = j1 * n + i0, c11 = j1 * n + i1,
                t = new Float2(u - fu, v - fv),
            };
        }

        /// <summary>HLSL <c>SnowCellsBlend(b, v00, v10, v01, v11)</c>: the four cells' values blended, along u first.</summary>
        public static float Blend(SnowCellBlend b, float v00, float v10, float v01, float v11) =>
            lerp(lerp(v00, v10, b.t.x), lerp(v01, v11, b.t.x), b.t.y);

        // (int) of a float truncates towards 0; the floor above makes the two agree except below -1,
        // where the clamp takes over anyway (HLSL: clamp((int2)f, 0, r - 1)).
        static int Clamp(int i, int r) => i < 0 ? 0 : (i > r - 1 ? r - 1 : i);
    }

    /// <summary>HLSL <c>SnowCellBlend</c>: a bilinear read's four cells (index j * R + i) and its fractions.</summary>
    internal struct SnowCellBlend
    {
        public int c00, c10, c01, c11;
        public Float2 t;
    }
}
