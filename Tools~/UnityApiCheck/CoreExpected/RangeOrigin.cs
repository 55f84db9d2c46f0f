namespace GregoryTerrain
{
    // As in core-range's RangeOrigin.cs.
    public struct RangeOrigin : System.IEquatable<RangeOrigin>
    {
        public Float2 hi, lo;
        public static readonly RangeOrigin zero = default;
        public Double2 Value => default;
        public static RangeOrigin For(TerrainRange range) => zero;
        public bool Equals(RangeOrigin o) => true;
    }
}
