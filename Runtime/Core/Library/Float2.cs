using System;

namespace GregoryTerrain
{
    /// <summary>Two floats, the GPU's float2. Reads like HLSL where Core mirrors the shaders.</summary>
    [Serializable]
    public struct Float2 : IEquatable<Float2>
    {
        /// <summary>The components.</summary>
        public float x, y;

        /// <summary>A vector of the given components.</summary>
        public Float2(float x, float y) { this.x = x; this.y = y; }

        /// <summary>Component-wise sum.</summary>
        public static Float2 operator +(Float2 a, Float2 b) => new Float2(a.x + b.x, a.y + b.y);
        /// <summary>Component-wise difference.</summary>
        public static Float2 operator -(Float2 a, Float2 b) => new Float2(a.x - b.x, a.y - b.y);
        /// <summary>Each component times <paramref name="s"/>.</summary>
        public static Float2 operator *(Float2 a, float s) => new Float2(a.x * s, a.y * s);
        /// <summary>Each component times <paramref name="s"/>.</summary>
        public static Float2 operator *(float s, Float2 a) => new Float2(a.x * s, a.y * s);

        /// <summary>True when no component is infinite or NaN.</summary>
        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y);

        /// <inheritdoc/>
        public bool Equals(Float2 o) => x.Equals(o.x) && y.Equals(o.y);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is Float2 o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(x, y);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R})");
    }
}
