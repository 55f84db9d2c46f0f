using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>
    /// Keeps the range origin (internals.md, "Range origin") across frames and re-snaps it only when the
    /// range has moved or shrunk so far from it that the local range would lose precision, so a frame
    /// normally sends <c>_Range</c> alone. The origin itself comes from Core's
    /// <see cref="RangeOrigin.For"/>; this type only decides when to ask for a new one.
    /// </summary>
    internal sealed class RangeOriginTracker
    {
        /// <summary>
        /// Re-snap once the range centre is farther from the origin than this many range widths: the
        /// local coordinates are then at most ~this many widths in size, and float keeps them to
        /// about 2^-24 of that, far below one vertex spacing (width / (tiles x 64)).
        /// </summary>
        public const double MaxDriftInWidths = 8.0;

        RangeOrigin _origin = RangeOrigin.zero;

        /// <summary>The origin in use.</summary>
        public RangeOrigin Origin => _origin;

        /// <summary>Forgets the origin, so the next <see cref="Update"/> snaps a new one.</summary>
        public void Reset() => _origin = RangeOrigin.zero;

        /// <summary>
        /// Returns true when the origin changed (then <c>_RangeOrigin</c> must be sent this frame).
        /// </summary>
        public bool Update(TerrainRange range)
        {
            RangeOrigin wanted = RangeOrigin.For(range);
            bool wantZero = wanted.Equals(RangeOrigin.zero);
            bool haveZero = _origin.Equals(RangeOrigin.zero);
            if (wantZero == haveZero && wantZero) return false;        // wide view: stays 0
            if (!wantZero && !haveZero)
            {
                Double2 o = _origin.Value;
                Double2 c = range.Center;
                double width = range.Width < range.Height ? range.Width : range.Height;
                double dx = c.x - o.x, dy = c.y - o.y;
                double limit = MaxDriftInWidths * width;
                if (dx * dx + dy * dy <= limit * limit) return false;   // near enough: keep it
            }
            _origin = wanted;
            return true;
        }
    }

    /// <summary>
    /// A <see cref="RangeOriginTracker"/> per camera, for views laid out around each camera (Horizon
    /// levels): cameras far apart keep their own origins, so none re-snaps when another one draws.
    /// Past <see cref="MaxCameras"/> cameras it forgets them all (each snaps once more).
    /// </summary>
    internal sealed class CameraRangeOrigins
    {
        public const int MaxCameras = 16;
        readonly Dictionary<int, RangeOriginTracker> _byCamera = new Dictionary<int, RangeOriginTracker>();

        /// <summary>The tracker of camera <paramref name="cameraId"/> (an instance ID), made on first use.</summary>
        public RangeOriginTracker For(int cameraId)
        {
            if (_byCamera.TryGetValue(cameraId, out RangeOriginTracker t)) return t;
            if (_byCamera.Count >= MaxCameras) _byCamera.Clear();
            _byCamera.Add(cameraId, t = new RangeOriginTracker());
            return t;
        }

        /// <summary>Forgets every camera's origin.</summary>
        public void Reset() => _byCamera.Clear();
    }
}
