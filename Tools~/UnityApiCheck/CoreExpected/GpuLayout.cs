namespace GregoryTerrain
{
    // EXPECTED: the only code that packs the GPU layout of internals.md.
    public static class GpuLayout
    {
        public static Float4[] ControlPoints(PatchGrid grid) => null;   // 20 per patch, w = 1
        public static Float4[] Regions(PatchGrid grid) => null;         // (a, b, e, f) per patch
        public static float[] GridLines(PatchGrid grid) => null;        // xLines then yLines
        public static Float4 GridSize(PatchGrid grid) => default;       // (n, m, 0, 0)
    }
}
