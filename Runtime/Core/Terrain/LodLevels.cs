using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// The level layout of the horizon-to-feet LOD (internals.md, "Levels of detail: from the feet to
    /// the horizon"): nested ranges around the camera's ground point, level k of width
    /// <c>W_k = 2^k W_0</c>, until one covers the terrain.
    /// <list type="bullet">
    /// <item><c>W_0 = 2^-n</c> of the terrain, so every level's cells (<c>W_k / M</c>) are dyadic and
    /// exact in float and double, and the terrain's far edge 1 lies on every lattice.</item>
    /// <item>Level k's corner is snapped to the cells of level k + 1 (<c>2 W_k / M</c>), so its
    /// boundary runs along the coarser level's cell lines: a seam is two fine cells per coarse cell
    /// (the T-junction rule needs it).</item>
    /// <item>A level wider than the space left at the terrain's edge is moved inside (on its lattice,
    /// since 1 is on it); with M &gt;= 8 the levels stay nested after snapping and moving.</item>
    /// </list>
    /// </summary>
    internal static class LodLevels
    {
        /// <summary>Fewest tiles per level side for which snapping keeps the levels nested.</summary>
        public const int MinTiles = 8;

        /// <summary>Levels needed for <c>W_0 = 2^-finestExponent</c>: widths 2^-n .. 2^0.</summary>
        public static int LevelCount(int finestExponent)
        {
            CheckExponent(finestExponent);
            return finestExponent + 1;
        }

        /// <summary>Tiles drawn by L levels of M^2: each coarser level's (M / 2)^2 under the finer one are culled.</summary>
        public static int DrawnTileCount(int levelCount, int tiles)
        {
            if (levelCount < 1) throw new ArgumentException(Invariant($"levelCount ({levelCount}) must be >= 1"), nameof(levelCount));
            if (tiles < 1) throw new ArgumentException(Invariant($"tiles ({tiles}) must be >= 1"), nameof(tiles));
            int half = tiles / 2;
            return tiles * tiles + (levelCount - 1) * (tiles * tiles - half * half);
        }

        /// <summary>
        /// The finest exponent n whose level 0, <c>2^-n</c> of a terrain <paramref name="terrainMeters"/>
        /// wide, is at least <paramref name="finestMeters"/> wide.
        /// </summary>
        public static int FinestExponent(double terrainMeters, double finestMeters)
        {
            if (!(terrainMeters > 0.0) || double.IsInfinity(terrainMeters))
                throw new ArgumentException(Invariant($"terrainMeters ({terrainMeters:R}) must be finite and greater than 0"), nameof(terrainMeters));
            if (!(finestMeters > 0.0) || double.IsInfinity(finestMeters))
                throw new ArgumentException(Invariant($"finestMeters ({finestMeters:R}) must be finite and greater than 0"), nameof(finestMeters));
            int n = (int)Math.Floor(Math.Log(terrainMeters / finestMeters, 2.0) + 1e-12);
            return Math.Max(0, Math.Min(n, 40));
        }

        /// <summary>
        /// The ranges of every level for a camera over <paramref name="ground"/> (terrain space, clamped
        /// into the unit square) into <paramref name="levels"/> (length at least <see cref="LevelCount"/>),
        /// finest first; returns how many.
        /// </summary>
        public static int Layout(Double2 ground, int finestExponent, int tiles, Span<TerrainRange> levels)
        {
            int count = LevelCount(finestExponent);
            if (tiles < MinTiles || tiles > 64)
                throw new ArgumentException(Invariant($"tiles ({tiles}) must lie in [{MinTiles}, 64]"), nameof(tiles));
            if (!ground.IsFinite) throw new ArgumentException($"ground {ground} must be finite", nameof(ground));
            if (levels.Length < count)
                throw new ArgumentException(Invariant($"levels.Length ({levels.Length}) must be at least {count}"), nameof(levels));
            double x = GMath.clamp(ground.x, 0.0, 1.0), y = GMath.clamp(ground.y, 0.0, 1.0);
            for (int k = 0; k < count; k++)
            {
                double w = Math.Pow(2.0, k - finestExponent);   // exact: a power of two
                double coarseCell = 2.0 * w / tiles;
                double c = Corner(x, w, coarseCell), d = Corner(y, w, coarseCell);
                levels[k] = new TerrainRange(c, d, c + w, d + w);
            }
            return count;
        }

        static double Corner(double at, double width, double coarseCell)
        {
            if (width >= 1.0) return 0.0;
            double c = Math.Floor((at - 0.5 * width) / coarseCell) * coarseCell;
            return GMath.clamp(c, 0.0, 1.0 - width);
        }

        static void CheckExponent(int n)
        {
            if (n < 0 || n > 40) throw new ArgumentException(Invariant($"finestExponent ({n}) must lie in [0, 40]"), "finestExponent");
        }

        static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
    }
}
