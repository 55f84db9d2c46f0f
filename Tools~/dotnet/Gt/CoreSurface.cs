using System;

namespace GregoryTerrain.Rig
{
    /// <summary>Reference evaluations of the Gregory surface in double, for cameras and error measures.</summary>
    static class CoreSurface
    {
        /// <summary>The Gregory height (no noise) at global point (x, y), in double.</summary>
        public static double HeightAt(PatchGrid grid, double x, double y)
        {
            int p = grid.FindPatch(x, y);
            Region r = grid.RegionOf(p);
            Double2 uv = RangeMapping.LocalCoordinate(new Double2(x, y), r);
            return GregoryEval.Position(grid.Patches[p].Points, uv.x, uv.y).z;
        }
    }
}
