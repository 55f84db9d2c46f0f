using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// A Unity terrain's heightmap in the fitter's terms. Unity keeps heights as fractions of the
    /// terrain's height (<c>TerrainData.size.y</c>) in a square array <c>[z, x]</c> of
    /// <c>heightmapResolution</c> samples a side spanning <c>size.x</c> by <c>size.z</c> metres. A
    /// Gregory terrain's unit square is scaled to metres by its Transform, so with scale
    /// <c>(size.x, size.x, size.z)</c> its height z (object y) is in units of size.x:
    /// <c>z = fraction * size.y / size.x</c>, and row r of the array is y = r / (res - 1), as in Unity.
    /// </summary>
    internal static class TerrainHeights
    {
        /// <summary>Row-major heights in terrain units from Unity's <c>[z, x]</c> fractions.</summary>
        public static double[] FromUnity(float[,] fractions, double sizeX, double sizeY, double sizeZ)
        {
            if (fractions == null) throw new ArgumentNullException(nameof(fractions));
            CheckSize(sizeX, "size.x");
            CheckSize(sizeY, "size.y");
            CheckSize(sizeZ, "size.z");
            int rows = fractions.GetLength(0), cols = fractions.GetLength(1);
            if (rows < 2 || cols < 2) throw new ArgumentException($"heights are {cols} x {rows}, need at least 2 x 2.", nameof(fractions));
            var z = new double[rows * cols];
            double scale = sizeY / sizeX;
            for (int r = 0; r < rows; r++)
                for (int c = 0; c < cols; c++) z[r * cols + c] = fractions[r, c] * scale;
            return z;
        }

        static void CheckSize(double v, string field)
        {
            if (!(v > 0) || double.IsInfinity(v))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "terrain {0} = {1}, need a positive finite size in metres.", field, v), field);
        }
    }
}
