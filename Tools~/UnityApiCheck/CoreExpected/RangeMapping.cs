namespace GregoryTerrain
{
    // As in core-range's RangeMapping.cs.
    public static class RangeMapping
    {
        public static void EncodeRange(TerrainRange range, RangeOrigin origin, out Float4 rangeF, out Float4 rangeOriginF) { rangeF = default; rangeOriginF = default; }
    }
}
