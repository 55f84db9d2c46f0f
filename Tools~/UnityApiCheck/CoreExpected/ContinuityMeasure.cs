namespace GregoryTerrain
{
    // EXPECTED: position gap and normal angle across shared patch edges.
    public struct ContinuityReport
    {
        public double MaxPositionGap;
        public double MaxNormalAngleDegrees;
    }
    public static class ContinuityMeasure
    {
        public static ContinuityReport Measure(PatchGrid grid, int samplesPerEdge) => default;
    }
}
