using System;

namespace GregoryTerrain
{
    /// <summary>Two floats, the GPU's float2. Reads like HLSL where Core mirrors the shaders.</summary>
    [Serializable]
    public struct Float2 : IEquatable<Float2>
    {
        public float x, y;

        public Float2(float x, float y) { this.x = x; this.y = y; }

        public static Float2 operator +(Float2 a, Float2 b) => new Float2(a.x + b.x, a.y + b.y);
        public static Float2 operator -(Float2 a, Float2 b) => new Float2(a.x - b.x, a.y - b.y);
        public static Float2 operator *(Float2 a, float s) => new Float2(a.x * s, a.y * s);
        public static Float2 operator *(float s, Float2 a) => new Float2(a.x * s, a.y * s);

        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y);

        public bool Equals(Float2 o) => x.Equals(o.x) && y.Equals(o.y);
        public override bool Equals(object obj) => obj is Float2 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(x, y);
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R})");
    }
}
