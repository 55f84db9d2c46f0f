using System;
using System.Collections.Generic;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>
    /// One Unity Terrain tile in metres: its position (south-west corner), TerrainData.size, samples a
    /// side and heights as fractions of SizeY (row-major, south row first).
    /// </summary>
    internal sealed class TerrainTile
    {
        public readonly string Name;
        public readonly double X, Y, Z, SizeX, SizeY, SizeZ;
        public readonly int Resolution;
        public readonly double[] Heights;

        public TerrainTile(string name, double x, double z, double sizeX, double sizeY, double sizeZ, int resolution, double[] heights, double y = 0)
        {
            Name = name; X = x; Y = y; Z = z; SizeX = sizeX; SizeY = sizeY; SizeZ = sizeZ; Resolution = resolution; Heights = heights;
        }
    }

    /// <summary>
    /// Unity Terrain tiles of equal size and resolution filling a rectangle edge to edge (sharing their
    /// edge samples, as Unity's neighbours do) converted into one grid: the south-west tile is fitted
    /// first, each other one against its west and/or south neighbour (HeightmapFitter.FitEastOf,
    /// FitNorthOf, FitNorthEastOf), then PatchGridJoin joins them, G1 across every seam.
    /// </summary>
    internal static class TileGroupAuthoring
    {
        /// <summary>Relative tolerance on positions and sizes (float Transforms of km-sized tiles).</summary>
        const double Tolerance = 1e-4;

        /// <summary>
        /// The tiles as <c>[i, j]</c>, i eastward, j northward. Throws ArgumentException naming the first
        /// tile of another size or resolution, off the others' lattice, on another tile, or missing.
        /// </summary>
        public static TerrainTile[,] Arrange(IReadOnlyList<TerrainTile> tiles)
        {
            if (tiles == null || tiles.Count == 0) throw new ArgumentException("no Terrain tiles selected.", nameof(tiles));
            TerrainTile a = tiles[0];
            double x0 = double.PositiveInfinity, z0 = double.PositiveInfinity;
            foreach (TerrainTile t in tiles)
            {
                if (!Same(t.SizeX, a.SizeX) || !Same(t.SizeY, a.SizeY) || !Same(t.SizeZ, a.SizeZ) || t.Resolution != a.Resolution)
                    throw Refusal($"tile '{t.Name}' is {t.SizeX} x {t.SizeY} x {t.SizeZ} m at {t.Resolution} samples, '{a.Name}' is {a.SizeX} x {a.SizeY} x {a.SizeZ} m at {a.Resolution}: the tiles must be of equal size and resolution.");
                x0 = Math.Min(x0, t.X); z0 = Math.Min(z0, t.Z);
            }
            var cells = new Dictionary<(int, int), TerrainTile>();
            int columns = 0, rows = 0;
            foreach (TerrainTile t in tiles)
            {
                double fi = (t.X - x0) / a.SizeX, fj = (t.Z - z0) / a.SizeZ;
                int i = (int)Math.Round(fi), j = (int)Math.Round(fj);
                if (Math.Abs(fi - i) > Tolerance || Math.Abs(fj - j) > Tolerance)
                    throw Refusal($"tile '{t.Name}' at ({t.X}, {t.Z}) is not edge to edge with the others: the tiles must be adjacent, {a.SizeX} x {a.SizeZ} m apart.");
                if (cells.TryGetValue((i, j), out TerrainTile other))
                    throw Refusal($"tile '{t.Name}' lies on tile '{other.Name}': the tiles must not overlap.");
                cells[(i, j)] = t;
                columns = Math.Max(columns, i + 1); rows = Math.Max(rows, j + 1);
            }
            var grid = new TerrainTile[columns, rows];
            for (int j = 0; j < rows; j++)
                for (int i = 0; i < columns; i++)
                    if (!cells.TryGetValue((i, j), out grid[i, j]))
                        throw Refusal($"no tile at column {i}, row {j} ({x0 + i * a.SizeX}, {z0 + j * a.SizeZ}) of the {columns} x {rows} group: the tiles must fill a rectangle.");
            return grid;
        }

        /// <summary>
        /// Every tile fitted with <paramref name="columns"/> x <paramref name="rows"/> patches, joined;
        /// max and RMS error over all tiles in fractions of SizeY. Cancelling throws OperationCanceledException.
        /// </summary>
        public static PatchGrid FitAndJoin(TerrainTile[,] tiles, int columns, int rows, out double maxError, out double rmsError,
            IProgress<float> progress = null, CancellationToken cancellationToken = default)
        {
            int n = tiles.GetLength(0), m = tiles.GetLength(1), res = tiles[0, 0].Resolution;
            var fits = new HeightmapFit[n, m];
            maxError = 0; double squares = 0;
            for (int j = 0; j < m; j++)
                for (int i = 0; i < n; i++)
                {
                    var part = new Share(progress, (j * n + i) / (float)(n * m), 1f / (n * m));
                    double[] z = tiles[i, j].Heights;
                    HeightmapFit fit = i == 0 && j == 0 ? HeightmapFitter.Fit(z, res, res, columns, rows, part, cancellationToken)
                        : j == 0 ? HeightmapFitter.FitEastOf(fits[i - 1, j], z, res, res, columns, part, cancellationToken)
                        : i == 0 ? HeightmapFitter.FitNorthOf(fits[i, j - 1], z, res, res, rows, part, cancellationToken)
                        : HeightmapFitter.FitNorthEastOf(fits[i - 1, j], fits[i, j - 1], z, res, res, part, cancellationToken);
                    fits[i, j] = fit;
                    maxError = Math.Max(maxError, fit.MaxError);
                    squares += fit.RmsError * fit.RmsError;   // equal sample counts: the mean of squares is the group's
                }
            rmsError = Math.Sqrt(squares / (n * m));
            PatchGrid joined = null;
            for (int j = 0; j < m; j++)
            {
                PatchGrid strip = fits[0, j].Grid;
                for (int i = 1; i < n; i++) strip = PatchGridJoin.WestEast(strip, fits[i, j].Grid, i / (double)(i + 1));
                joined = j == 0 ? strip : PatchGridJoin.SouthNorth(joined, strip, j / (double)(j + 1));
            }
            return joined;
        }

        static bool Same(double a, double b) => Math.Abs(a - b) <= Tolerance * Math.Max(Math.Abs(a), Math.Abs(b));

        static ArgumentException Refusal(FormattableString s) => new ArgumentException(s.ToString(CultureInfo.InvariantCulture), "tiles");

        /// <summary>One tile's share of the group's progress.</summary>
        sealed class Share : IProgress<float>
        {
            readonly IProgress<float> _whole;
            readonly float _start, _length;
            public Share(IProgress<float> whole, float start, float length) { _whole = whole; _start = start; _length = length; }
            public void Report(float value) => _whole?.Report(_start + value * _length);
        }
    }
}
