using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The part <c>[a, e] x [b, f]</c> of the terrain's unit square that one patch covers
    /// (the paper's region info, sent to the GPU once as the float4 <c>(a, b, e, f)</c>).
    /// </summary>
    internal struct Region : IEquatable<Region>
    {
        public double a, b, e, f;

        public Region(double a, double b, double e, double f) { this.a = a; this.b = b; this.e = e; this.f = f; }

        public double Width => e - a;
        public double Height => f - b;

        public bool Contains(double x, double y) => x >= a && x <= e && y >= b && y <= f;

        public bool Equals(Region o) => a.Equals(o.a) && b.Equals(o.b) && e.Equals(o.e) && f.Equals(o.f);
        public override bool Equals(object obj) => obj is Region o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(a, b, e, f);
        public override string ToString() => FormattableString.Invariant($"[{a:R}, {e:R}] x [{b:R}, {f:R}]");
    }
}
