using System;

namespace GregoryTerrain
{
    /// <summary>Four floats, the GPU's float4: what a shader constant such as <c>_Range</c> holds.</summary>
    internal struct Float4 : IEquatable<Float4>
    {
        public float x, y, z, w;

        public Float4(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public Float4(Float3 xyz, float w) { x = xyz.x; y = xyz.y; z = xyz.z; this.w = w; }

        public static readonly Float4 zero = default;

        public Float2 xy => new Float2(x, y);
        public Float2 zw => new Float2(z, w);
        public Float3 xyz => new Float3(x, y, z);

        public static Float4 operator +(Float4 a, Float4 b) => new Float4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
        public static Float4 operator -(Float4 a, Float4 b) => new Float4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w);
        public static Float4 operator *(Float4 a, float s) => new Float4(a.x * s, a.y * s, a.z * s, a.w * s);
        public static Float4 operator *(float s, Float4 a) => new Float4(a.x * s, a.y * s, a.z * s, a.w * s);

        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y) && GMath.isfinite(z) && GMath.isfinite(w);

        public bool Equals(Float4 o) => x.Equals(o.x) && y.Equals(o.y) && z.Equals(o.z) && w.Equals(o.w);
        public override bool Equals(object obj) => obj is Float4 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(x, y, z, w);
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R}, {z:R}, {w:R})");
    }
}
