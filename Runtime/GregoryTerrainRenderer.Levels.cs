using UnityEngine;

namespace GregoryTerrain
{
    // Horizon levels (internals.md): L nested levels of M x M tiles around each camera's ground point,
    // one draw with GT_LOD; per camera and frame only _Ranges (one float4 a level), _LodLevels on change.
    public sealed partial class GregoryTerrainRenderer
    {
        /// <summary>Narrowest level, in metres: the level at the feet is the first power-of-two part of the terrain at least this wide.</summary>
        internal const double FinestLevelMeters = 16.0;

        /// <summary>On-screen length (pixels) of a segment under the levels' continuous octave rule (_NoiseOctaves.z).</summary>
        internal const float LevelSegmentPixels = 2f;

        readonly TerrainRange[] _levelRanges = new TerrainRange[LodTiles.MaxLevels];
        readonly Vector4[] _levelVectors = new Vector4[LodTiles.MaxLevels];
        int _levelCount;      // levels laid out for the camera being drawn (Prepare), then sent (0: none yet)

        /// <summary>The property ID of <c>_LodLevels</c> (for the Unity-side tests).</summary>
        internal static int LodLevelsPropertyId => ShaderIds.LodLevels;

        /// <summary>Whether the draw uses the levels: the setting, with the tessellator (the fallback grid draws one range).</summary>
        bool LevelsOn(bool fallback) => horizonLevels && !fallback;

        /// <summary>The levels' settings check: M even and at least LodLevels.MinTiles. Null when drawable.</summary>
        string LevelsSettingsError()
        {
            if (tiles % 2 != 0 || tiles < LodLevels.MinTiles)
                return $"tiles ({tiles}) must be even and at least {LodLevels.MinTiles} with Horizon Levels (a finer level covers M / 2 tiles of the coarser one)";
            return null;
        }

        /// <summary>The levels around <paramref name="cam"/>'s ground point (through <see cref="WorldFrame"/>), into the preallocated ranges; returns how many.</summary>
        int LayoutLevels(Camera cam)
        {
            Double3 local = WorldToTerrainObject(cam.transform.position);   // object space: (x, height, y)
            return LodLevels.Layout(new Double2(local.x, local.z), FinestExponent(), tiles, _levelRanges);
        }

        /// <summary>The finest level's exponent for the terrain's width in world units.</summary>
        int FinestExponent()
        {
            double metres = WorldUnitsPerObjectUnit.x;   // world units across the terrain's x
            if (!(metres > 0.0) || double.IsInfinity(metres)) metres = 1.0;
            return System.Math.Min(LodLevels.FinestExponent(metres, FinestLevelMeters), LodTiles.MaxLevels - 1);
        }

        /// <summary>Horizon levels drawn (L), 0 for one range.</summary>
        internal int LevelCount => LevelsOn(DrawsFallback) ? LodLevels.LevelCount(FinestExponent()) : 0;

        /// <summary>This draw's origin tracker: with the levels <paramref name="cam"/>'s own, else the range's.</summary>
        RangeOriginTracker OriginTracker(Camera cam, bool fallback) =>
            cam != null && LevelsOn(fallback) ? _cameraOrigins.For(cam.GetInstanceID()) : _rangeOrigin;

        /// <summary>
        /// Lays the levels out around <paramref name="cam"/> (sent by <see cref="PushLevels"/>) and returns
        /// the range the origin follows: the finest level (on a terrain wider than ~4 km the feet then
        /// output S(q) - S(O) precisely, precision.md), else the renderer's range.
        /// </summary>
        TerrainRange OriginRange(Camera cam, bool fallback)
        {
            if (cam == null || !LevelsOn(fallback)) return _range;
            _levelCount = LayoutLevels(cam);
            return _levelRanges[0];
        }

        /// <summary>Sends <see cref="OriginRange"/>'s levels relative to the origin, one float4 each; returns the tiles drawn (L x M^2).</summary>
        int PushLevels()
        {
            int count = _levelCount;
            for (int k = 0; k < count; k++)
            {
                RangeMapping.EncodeRange(_levelRanges[k], _origin.Origin, out Float4 r, out _);
                _levelVectors[k] = ToVector(r);
            }
            _props.SetVectorArray(ShaderIds.Ranges, _levelVectors);
            _setLastPrepare.Add(ShaderIds.Ranges);
            if (count != _sent.levelCount)
            {
                SetVector(ShaderIds.LodLevels, new Vector4(count, 0f, 0f, 0f));
                _sent.levelCount = count;
            }
            return count * tiles * tiles;
        }
    }
}
