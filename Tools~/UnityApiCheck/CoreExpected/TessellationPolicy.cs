namespace GregoryTerrain
{
    // EXPECTED: triangles M x M tiles produce at most at the given max factor.
    public static class TessellationPolicy
    {
        public static long EstimateTriangleCount(int tiles, float maxFactor) => 0;
    }
}
