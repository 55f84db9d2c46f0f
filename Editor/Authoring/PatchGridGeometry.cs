using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// Geometry a valid grid may still hold that cannot be drawn sensibly: a patch whose normal is
    /// zero (collapsed, all control points on a line or a point) or points down or sideways (the
    /// patch is mirrored or flipped, so lighting and culling turn it inside out). Warnings, not
    /// errors: the grid loads and draws; the inspector and <c>gt-cli check</c> show them.
    /// </summary>
    internal static class PatchGridGeometry
    {
        /// <summary>Warnings listed by <see cref="Warnings"/> before the rest are only counted.</summary>
        public const int MaxListed = 20;

        /// <summary>
        /// A normal shorter than this fraction of its region's area (what a flat patch's normal
        /// measures) counts as zero: the patch is collapsed there.
        /// </summary>
        public const double ZeroNormalFraction = 1e-9;

        /// <summary>Parameters where each patch is checked: corners, edge midpoints and the centre.</summary>
        static readonly double[] Samples = { 0.0, 0.5, 1.0 };

        /// <summary>
        /// One line per patch with a problem (the first problem found on it), naming the patch index
        /// p, its (i, j) and the (u, v) where the normal is zero or points down; at most
        /// <see cref="MaxListed"/> lines, then one line counting the rest. Empty for a sound grid.
        /// </summary>
        public static List<string> Warnings(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            var warnings = new List<string>();
            int more = 0;
            for (int p = 0; p < grid.PatchCount; p++)
            {
                string w = Check(grid, p);
                if (w == null) continue;
                if (warnings.Count < MaxListed) warnings.Add(w);
                else more++;
            }
            if (more > 0) warnings.Add(string.Format(CultureInfo.InvariantCulture, "... and {0} more patches with the same kinds of problem.", more));
            return warnings;
        }

        /// <summary>The warning for patch <paramref name="p"/>, or null when it draws sensibly.</summary>
        public static string Check(PatchGrid grid, int p)
        {
            Region r = grid.RegionOf(p);
            double area = (r.e - r.a) * (r.f - r.b);
            Double3[] cp = grid.Patches[p].Points;
            foreach (double v in Samples)
                foreach (double u in Samples)
                {
                    GregoryEval.Evaluate(cp, u, v, out _, out Double3 du, out Double3 dv);
                    Double3 n = GMath.cross(du, dv);
                    double length = GMath.length(n);
                    if (!(length > ZeroNormalFraction * area))
                        return Say(grid, p, u, v, "has a zero normal (the patch is collapsed to a line or a point there)");
                    if (!(n.z > 0))
                        return Say(grid, p, u, v, string.Format(CultureInfo.InvariantCulture,
                            "has a normal pointing {0} (z = {1:G3} of {2:G3}): the patch is mirrored or flipped", n.z < 0 ? "down" : "sideways", n.z, length));
                }
            return null;
        }

        static string Say(PatchGrid grid, int p, double u, double v, string what) =>
            string.Format(CultureInfo.InvariantCulture, "patch {0} ({1}, {2}) at (u, v) = ({3}, {4}) {5}.", p, p % grid.Columns, p / grid.Columns, u, v, what);
    }
}
