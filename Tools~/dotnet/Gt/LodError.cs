using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The screen error of a levels-of-detail view (Tools~/rig/README.md, "Levels of detail: measurements", screen error):
    /// every drawn tile cut into the cells of the integer factors the GPU gave it (GT_FACTOR_READBACK),
    /// its vertices where the vertex stage puts them (Core's float mirror: float range mapping, the
    /// continuous octave rule, float positions) and, at the vertices, edge midpoints and cell centres,
    /// the distance to the full-detail surface (Gregory + every noise octave, double) at the same
    /// (u, v). Two pixel figures: "bound" is ErrorMeasure's (3D distance times the largest pixels a
    /// unit covers there: what the tessellation target bounds), "screen" is where the drawn triangle
    /// shows the sample (vertices projected by the float matrix, as the GPU does) against where the
    /// exact point projects in double: what the eye sees, float transform included.
    /// </summary>
    static class LodError
    {
        public static string Measure(LodScene s, PatchFactors[] factors, int maxCells)
        {
            if (factors.Length != s.Patches) throw new ArgumentException($"{factors.Length} patch factors given, {s.Patches} patches drawn");
            ErrorResult r = ErrorMeasure.Measure(s.DrawnObjectPoint, s.ExactObjectPoint, factors, s.Camera, fractionalOdd: false, maxCellsPerPatch: maxCells);
            double m = s.TerrainMeters;
            return FormattableString.Invariant(
                $"lod_error max_px {r.MaxScreenPixels:G4} rms_px {r.RmsScreenPixels:G4} bound_max_px {r.MaxPixels:G4} bound_rms_px {r.RmsPixels:G4} max_m {r.MaxWorld * m:G4} rms_m {r.RmsWorld * m:G4} samples {r.Samples} triangles_model {r.Triangles} culled {r.CulledPatches}");
        }

        /// <summary>
        /// <see cref="Measure"/> one level at a time (the other levels' tiles taken as culled): one
        /// "lod_level k triangles T max_px X rms_px Y bound_max_px B culled C" line per level.
        /// </summary>
        public static string MeasureLevels(LodScene s, PatchFactors[] factors, int maxCells)
        {
            if (factors.Length != s.Patches) throw new ArgumentException($"{factors.Length} patch factors given, {s.Patches} patches drawn");
            int perLevel = LodTiles.TilesPerLevel(s.Tiles);
            var lines = new System.Text.StringBuilder();
            for (int level = 0; level < s.LevelCount; level++)
            {
                var f = new PatchFactors[factors.Length];
                for (int p = 0; p < f.Length; p++)
                    f[p] = p / perLevel == level ? factors[p] : new PatchFactors { culled = true };
                ErrorResult r = ErrorMeasure.Measure(s.DrawnObjectPoint, s.ExactObjectPoint, f, s.Camera, fractionalOdd: false, maxCellsPerPatch: maxCells);
                lines.AppendLine(FormattableString.Invariant(
                    $"lod_level {level} triangles {r.Triangles} max_px {r.MaxScreenPixels:G4} rms_px {r.RmsScreenPixels:G4} bound_max_px {r.MaxPixels:G4} culled {r.CulledPatches - (s.LevelCount - 1) * perLevel}"));
            }
            return lines.ToString().TrimEnd();
        }
    }
}