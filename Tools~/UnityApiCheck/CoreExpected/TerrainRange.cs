namespace GregoryTerrain
{
    // As in core-range's TerrainRange.cs.
    public struct TerrainRange
    {
        public double c, d, g, h;
        public TerrainRange(double c, double d, double g, double h) { this.c = c; this.d = d; this.g = g; this.h = h; }
        public static readonly TerrainRange full = new TerrainRange(0, 0, 1, 1);
        public double Width => g - c;
        public double Height => h - d;
        public Double2 Center => new Double2(0.5 * (c + g), 0.5 * (d + h));
        public void Validate(string name = "range") { }
    }
}
