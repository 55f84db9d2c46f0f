namespace GregoryTerrain
{
    /// <summary>
    /// Builds a valid <see cref="TerrainRange"/> for the range controllers: a rectangle of a given
    /// size around a point, shrunk to fit the unit square and shifted back inside it (never clipped,
    /// so the view keeps its aspect ratio). Allocation-free; used every frame.
    /// </summary>
    public static class RangeFit
    {
        /// <summary>Smallest range width the controllers produce (precision.md says what holds that deep).</summary>
        public const double MinWidth = 1e-7;

        /// <summary>A range of <paramref name="width"/> x <paramref name="height"/> centred on (cx, cy), inside [0,1]^2.</summary>
        public static TerrainRange Around(double cx, double cy, double width, double height)
        {
            width = Clamp(double.IsNaN(width) ? 1.0 : width, MinWidth, 1.0);
            height = Clamp(double.IsNaN(height) ? 1.0 : height, MinWidth, 1.0);
            double c = Clamp(double.IsNaN(cx) ? 0.5 : cx - 0.5 * width, 0.0, 1.0 - width);
            double d = Clamp(double.IsNaN(cy) ? 0.5 : cy - 0.5 * height, 0.0, 1.0 - height);
            // g = c + width may round above 1 by one ulp; the range must stay inside the square.
            double g = c + width > 1.0 ? 1.0 : c + width;
            double h = d + height > 1.0 ? 1.0 : d + height;
            return new TerrainRange(c, d, g, h);
        }

        static double Clamp(double v, double lo, double hi) => v < lo ? lo : v > hi ? hi : v;
    }
}
