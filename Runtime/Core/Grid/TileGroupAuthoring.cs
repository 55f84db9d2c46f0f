using System;
using System.Collections.Generic;
using System.Globalization;
using System.Threading;

namespace GregoryTerrain
{
    /// <summary>One Unity Terrain tile: its name, south-west corner and size in metres, and its heights.</summary>
    internal sealed class TerrainTile
    {
        public string Name { get; }
        /// <summary>World x and z of the tile's south-west corner (the Terrain's position), metres.</summary>
        public double X { get; }
        public double Z { get; }
        /// <summary>World y of the tile's base, metres (carried to the converted terrain).</summary>
        public double Y { get; }
        /// <summary>TerrainData.size: width (x), height (y) and length (z), metres.</summary>
        public double SizeX { get; }
        public double SizeY { get; }
        public double SizeZ { get; }
        /// <summary>Samples a side (heightmapResolution) and the heights as fractions of SizeY, row-major, south row first.</summary>
        public int Resolution { get; }
        public double[] Heights { get; }

        public TerrainTile(string name, double x, double z, double sizeX, double sizeY, double sizeZ, int resolution, double[] heights, double y = 0)
        {
            Name = name; X = x; Y = y; Z = z; SizeX = sizeX; SizeY = sizeY; SizeZ = sizeZ; Resolution = resolution; Heights = heights;
        }
    }

    /// <summary>
    /// Converts a group of Unity Terrain tiles into one seamless grid: the tiles must be of equal size
    /// and resolution and fill a rectangle edge to edge (as Unity's neighbouring terrains do, sharing
    /// their edge samples). The south-west tile is fitted first; each other tile continues its west
    /// neighbour (<see cref="HeightmapFitter.FitEastOf"/>), its south neighbour (FitNorthOf) or both
    /// (FitNorthEastOf), and <see cref="PatchGridJoin"/> joins them, G1 across every seam. Heights are
    /// the tiles' fractions: with Height Scale = SizeY they are metres on the renderer.
    /// </summary>
    internal static class TileGroupAuthoring
    {
        /// <summary>Relative tolerance on positions and sizes (float Transforms of km-sized tiles).</summary>
        const double Tolerance = 1e-4;

        /// <summary>
        /// The tiles by column and row, <c>[i, j]</c>, i eastward and j northward. Throws
        /// ArgumentException naming the first tile that is of another size or resolution, overlaps
        /// another, or leaves the group short of a full rectangle.
        /// </summary>
        public static TerrainTile[,] Arrange(IReadOnlyList<TerrainTile> tiles)
        {
            if (tiles == null || tiles.Count == 0) throw new ArgumentException("no Terrain tiles selected.", nameof(tiles));
            TerrainTile first = tiles[0];
            double x0 = double.PositiveInfinity, z0 = double.PositiveInfinity;
            foreach (TerrainTile t in tiles)
            {
                if (!Same(t.SizeX, first.SizeX) || !Same(t.SizeY, first.SizeY) || !Same(t.SizeZ, first.SizeZ) || t.Resolution != first.Resolution)
                    throw new ArgumentException(Invariant($"tile '{t.Name}' is {t.SizeX} x {t.SizeY} x {t.SizeZ} m at {t.Resolution} samples, '{first.Name}' is {first.SizeX} x {first.SizeY} x {first.SizeZ} m at {first.Resolution}: the tiles must be of equal size and resolution."), nameof(tiles));
                x0 = Math.Min(x0, t.X); z0 = Math.Min(z0, t.Z);
            }
            var cells = new Dictionary<(int, int), TerrainTile>();
            int columns = 0, rows = 0;
            foreach (TerrainTile t in tiles)
            {
                double fi = (t.X - x0) / first.SizeX, fj = (t.Z - z0) / first.SizeZ;
                int i = (int)Math.Round(fi), j = (int)Math.Round(fj);
                if (Math.Abs(fi - i) > Tolerance || Math.Abs(fj - j) > Tolerance)
                    throw new ArgumentException(Invariant($"tile '{t.Name}' at ({t.X}, {t.Z}) is not edge to edge with the others: the tiles must be adjacent, {first.SizeX} x {first.SizeZ} m apart."), nameof(tiles));
                if (cells.TryGetValue((i, j), out TerrainTile other))
                    throw new ArgumentException($"tile '{t.Name}' lies on tile '{other.Name}': the tiles must not overlap.", nameof(tiles));
                cells[(i, j)] = t;
                columns = Math.Max(columns, i + 1); rows = Math.Max(rows, j + 1);
            }
            var grid = new TerrainTile[columns, rows];
            for (int j = 0; j < rows; j++)
                for (int i = 0; i < columns; i++)
                {
                    if (!cells.TryGetValue((i, j), out grid[i, j]))
                        throw new ArgumentException(Invariant($"no tile at column {i}, row {j} ({x0 + i * first.SizeX}, {z0 + j * first.SizeZ}) of the {columns} x {rows} group: the tiles must fill a rectangle."), nameof(tiles));
                }
            return grid;
        }

        /// <summary>
        /// Fits every tile with <paramref name="columns"/> x <paramref name="rows"/> patches and joins
        /// them into one grid; max and RMS error over all tiles come back in height units (fractions
        /// of SizeY). Cancellation throws OperationCanceledException and nothing is returned.
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
                    int done = j * n + i;
                    var part = new Progress01(progress, done / (float)(n * m), 1f / (n * m));
                    double[] z = tiles[i, j].Heights;
                    fits[i, j] = i == 0 && j == 0 ? HeightmapFitter.Fit(z, res, res, columns, rows, part, cancellationToken)
                        : j == 0 ? HeightmapFitter.FitEastOf(fits[i - 1, j], z, res, res, columns, part, cancellationToken)
                        : i == 0 ? HeightmapFitter.FitNorthOf(fits[i, j - 1], z, res, res, rows, part, cancellationToken)
                        : HeightmapFitter.FitNorthEastOf(fits[i - 1, j], fits[i, j - 1], z, res, res, part, cancellationToken);
                    maxError = Math.Max(maxError, fits[i, j].MaxError);
                    squares += fits[i, j].RmsError * fits[i, j].RmsError;
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

        static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);

        /// <summary>One tile's share of the whole group's progress.</summary>
        sealed class Progress01 : IProgress<float>
        {
            readonly IProgress<float> _whole;
            readonly float _start, _length;
            public Progress01(IProgress<float> whole, float start, float length) { _whole = whole; _start = start; _length = length; }
            public void Report(float value) => _whole?.Report(_start + value * _length);
        }
    }
}
