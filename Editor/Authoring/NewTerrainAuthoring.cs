using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// A new terrain as GameObject &gt; 3D Object &gt; Gregory Terrain makes it, in metres (Transform
    /// scale 1): Unity Terrain's default 1000 x 1000 m and 600 m height, on a flat grid fine enough that
    /// the sculpt brush's default radius reaches several control points; and how far apart a grid's
    /// control points are in metres, which the brush must reach to move anything.
    /// </summary>
    internal static class NewTerrainAuthoring
    {
        /// <summary>Terrain Size (x and y, metres) and Height Scale (metres per height unit): Unity Terrain's defaults.</summary>
        public const double SizeMetres = 1000.0, HeightMetres = 600.0;

        /// <summary>
        /// Patches a side: control points 1000 / (64 * 3) = 5.2 m apart under a 50 m brush. 4,096
        /// patches are 1.9 MB of control points in 64 blocks, made in milliseconds.
        /// </summary>
        public const int Patches = 64;

        /// <summary>The sculpt brush's radius when the editor starts, metres.</summary>
        public const double DefaultBrushMetres = 50.0;

        /// <summary>The new terrain's flat grid.</summary>
        public static PatchGrid CreateGrid() => PatchGrid.CreateFlat(Patches, Patches);

        /// <summary>
        /// The largest distance in metres between neighbouring control points along x or y: a patch w
        /// metres wide has points w / 3 apart. A brush at least this wide always has a control point
        /// within 0.71 of its radius (falloff 0.25 or more).
        /// </summary>
        public static double ControlPointSpacing(double[] xLines, double[] yLines, double sizeXMetres, double sizeYMetres)
        {
            if (xLines == null) throw new ArgumentNullException(nameof(xLines));
            if (yLines == null) throw new ArgumentNullException(nameof(yLines));
            CheckMetres(sizeXMetres, nameof(sizeXMetres));
            CheckMetres(sizeYMetres, nameof(sizeYMetres));
            return Math.Max(WidestInterval(xLines) * sizeXMetres, WidestInterval(yLines) * sizeYMetres) / 3.0;
        }

        /// <summary>The brush radius the sculpt tool uses: at least the control-point spacing, so a dab always moves the surface.</summary>
        public static double ClampBrushRadius(double radiusMetres, double spacingMetres) => Math.Max(radiusMetres, spacingMetres);

        static double WidestInterval(double[] lines)
        {
            double widest = 0;
            for (int k = 1; k < lines.Length; k++) widest = Math.Max(widest, lines[k] - lines[k - 1]);
            return widest;
        }

        static void CheckMetres(double v, string field)
        {
            if (!(v > 0) || double.IsInfinity(v))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "{0} = {1}, need a positive finite size in metres.", field, v), field);
        }
    }
}
