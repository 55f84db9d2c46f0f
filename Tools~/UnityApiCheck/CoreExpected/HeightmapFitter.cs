using System;
using System.Threading;
namespace GregoryTerrain
{
    // EXPECTED: heights row-major (width x height samples, row 0 at y = 0), in terrain units.
    public static class HeightmapFitter
    {
        public static PatchGrid Fit(float[] heights, int width, int height, int columns, int rows,
                                    IProgress<float> progress, CancellationToken cancellation) => null;
    }
}
