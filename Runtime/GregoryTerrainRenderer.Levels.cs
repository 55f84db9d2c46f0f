using UnityEngine;

namespace GregoryTerrain
{
    // Horizon levels (internals.md, "Levels of detail: from the feet to the horizon"): instead of one
    // range, L nested levels of M x M tiles around each camera's ground point, drawn in one call with
    // GT_LOD. Per camera and frame the only values sent are the levels' ranges, one float4 each, in
    // one preallocated array (_Ranges); _LodLevels only when the level count changes.
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

        /// <summary>
        /// Lays the levels out around <paramref name="cam"/>'s ground point into the preallocated
        /// ranges and returns how many. The ground point and the terrain's width in metres come from
        /// <see cref="WorldFrame"/> (Transform, Terrain Size, floating-origin offset), as the draw
        /// matrices, the queries and the collider do.
        /// </summary>
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
        /// Lays the levels out around <paramref name="cam"/> (once a camera and frame: <see cref="PushLevels"/>
        /// sends this layout) and returns the range the range origin follows
        /// (<see cref="RangeOriginTracker"/>): with the levels, the finest level around the camera, so
        /// on a large terrain (below RangeOrigin.DeepWidth of it, a terrain wider than ~4 km) the
        /// vertices output S(q) - S(O) near the feet from precise differences (precision.md) and the
        /// draw matrices cancel S(O) against the camera in double; otherwise the renderer's range.
        /// </summary>
        TerrainRange OriginRange(Camera cam, bool fallback)
        {
            if (cam == null || !LevelsOn(fallback)) return _range;
            _levelCount = LayoutLevels(cam);
            return _levelRanges[0];
        }

        /// <summary>
        /// Sends the levels <see cref="OriginRange"/> laid out for this camera in <see cref="Prepare"/>,
        /// relative to the origin: one float4 per level. Returns how many tiles the draw holds (L x M^2).
        /// </summary>
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
