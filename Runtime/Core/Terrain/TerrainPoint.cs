using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A global point <c>q = originHi + local</c> as the shaders carry it: two floats per axis.
    /// <c>originHi</c> is the float-exact high part of the range origin, the same for every vertex of
    /// a frame; <c>local</c> is small at deep zoom, so its float has fine absolute resolution there
    /// (near q ~ 0.7 a plain float q resolves only ~6e-8; a local offset of ~1e-6 resolves ~1e-13).
    /// Mirrors <c>struct TerrainPoint</c> in Shaders/Library/RangeMapping.hlsl.
    /// </summary>
    [Serializable]
    internal struct TerrainPoint : IEquatable<TerrainPoint>
    {
        public Float2 originHi;
        public Float2 local;

        public TerrainPoint(Float2 originHi, Float2 local) { this.originHi = originHi; this.local = local; }

        /// <summary>A plain float point: origin 0, everything in <c>local</c> (the paper's path).</summary>
        public static TerrainPoint FromFloat(Float2 q) => new TerrainPoint(default, q);

        /// <summary>
        /// The exact value <c>originHi + local</c> in double. Exact because both are floats whose
        /// exponents differ by less than 53 - 24 bits for any point of the unit square a shader makes.
        /// </summary>
        public Double2 ToDouble() => new Double2((double)originHi.x + local.x, (double)originHi.y + local.y);

        public bool Equals(TerrainPoint o) => originHi.Equals(o.originHi) && local.Equals(o.local);
        public override bool Equals(object obj) => obj is TerrainPoint o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(originHi, local);
        public override string ToString() => FormattableString.Invariant($"{originHi} + {local}");
    }
}
