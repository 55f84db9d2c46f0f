using System;

namespace GregoryTerrain.Samples.TerrainFlyover
{
    /// <summary>
    /// The fly-over's loop and height rule without Unity types, so that FlyoverCamera runs it every
    /// frame and the package's rig walks the same arithmetic over the sample's surface in a test.
    /// Positions are in the terrain's unit square (x, y); heights are world metres.
    /// </summary>
    public static class FlyoverPath
    {
        /// <summary>Radius of the loop around the terrain's centre, as a fraction of the terrain's width.</summary>
        public const double LoopRadius = 0.3;

        /// <summary>Points along the look-ahead (the camera's own point is one more).</summary>
        public const int AheadSamples = 8;

        /// <summary>Loop angle that the camera looks towards, ahead of its own (radians).</summary>
        public const double LookAngle = 0.3;

        /// <summary>The loop's point at <paramref name="phase"/> (radians), in the unit square.</summary>
        public static void Point(double phase, out double x, out double y)
        {
            x = 0.5 + LoopRadius * Math.Cos(phase);
            y = 0.5 + LoopRadius * Math.Sin(phase);
        }

        /// <summary>1 at the widest range, 0 at the narrowest: zooms in and out twice per loop.</summary>
        public static double Zoom(double phase) => 0.5 + 0.5 * Math.Cos(2.0 * phase);

        /// <summary>The range's side at <paramref name="phase"/>, between the narrowest and widest (in their unit).</summary>
        public static double RangeWidth(double phase, double widest, double narrowest) =>
            narrowest + (widest - narrowest) * Zoom(phase);

        /// <summary>
        /// The highest surface (world metres) under the camera and at <see cref="AheadSamples"/> points
        /// of the loop in the next <paramref name="aheadRadians"/>; <paramref name="surface"/> gives the
        /// surface height at a unit-square point (NaN where there is none: skipped).
        /// </summary>
        public static double GroundAhead(double phase, double aheadRadians, Func<double, double, double> surface)
        {
            double highest = double.NegativeInfinity;
            for (int k = 0; k <= AheadSamples; k++)
            {
                Point(phase + aheadRadians * k / AheadSamples, out double x, out double y);
                double h = surface(x, y);
                if (h > highest) highest = h;
            }
            return highest;
        }

        /// <summary>
        /// The camera's next height (world metres): it eases towards <paramref name="clearance"/> over the
        /// highest ground ahead (1 - 1/e of the way in <paramref name="smoothSeconds"/>), so it climbs
        /// before a ridge and sinks gently after it, and never goes below that clearance over the
        /// ground under it. <paramref name="current"/> NaN (first frame): starts at the target. NaN
        /// when there is no ground under the camera.
        /// </summary>
        public static double NextHeight(double current, double groundUnder, double groundAhead,
                                        double clearance, double dt, double smoothSeconds)
        {
            if (double.IsNaN(groundUnder)) return double.NaN;
            double target = Math.Max(groundAhead, groundUnder) + clearance;
            double eased = double.IsNaN(current) ? target
                : current + (target - current) * (1.0 - Math.Exp(-Math.Max(dt, 0.0) / Math.Max(smoothSeconds, 1e-3)));
            return Math.Max(eased, groundUnder + clearance);
        }
    }
}
