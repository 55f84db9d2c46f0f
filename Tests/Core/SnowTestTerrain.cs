using System;

namespace GregoryTerrain.Tests
{
    /// <summary>Analytic snow fields for the snow tests (heights and exact normals written here, not by Core).</summary>
    static class SnowTestTerrain
    {
        public static SnowField Flat(int r, float height = 0f)
        {
            var f = new SnowField(r);
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                    f.Set(i, j, new Float3(0f, 0f, 1f), height);
            return f;
        }

        /// <summary>
        /// A straight ridge along y at x = 0.5: h = height * max(0, 1 - |x - 0.5| / halfWidth), so both
        /// faces have slope height / halfWidth; the normal is the exact one of the face, (-h'(x), 0, 1) normalised.
        /// </summary>
        public static SnowField Ridge(int r, float height, float halfWidth)
        {
            var f = new SnowField(r);
            double slope = height / halfWidth;
            for (int j = 0; j < r; j++)
                for (int i = 0; i < r; i++)
                {
                    double x = (i + 0.5) / r, d = x - 0.5;
                    double h = height * Math.Max(0.0, 1.0 - Math.Abs(d) / halfWidth);
                    double dh = Math.Abs(d) >= halfWidth ? 0.0 : -Math.Sign(d) * slope;
                    double len = Math.Sqrt(dh * dh + 1.0);
                    f.Set(i, j, new Float3((float)(-dh / len), 0f, (float)(1.0 / len)), (float)h);
                }
            return f;
        }

        /// <summary>The cell column nearest to x.</summary>
        public static int Column(int r, double x) => (int)Math.Floor(x * r);
    }
}
