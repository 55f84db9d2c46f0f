using System;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The range origin's tracking (Core): re-snapped only on a far move, and per camera for views laid out
    /// around each camera. Kept with the rig's tests, out of the shipped package (its size limit).
    /// </summary>
    [TestFixture]
    public class RangeOriginTrackerTests
    {
        // The finest Horizon level (16 m) around two cameras 10 km apart on a 100 km terrain.
        static readonly TerrainRange NearA = RangeAt(0.30), NearB = RangeAt(0.40);

        static TerrainRange RangeAt(double x) => new TerrainRange(x, 0.5, x + 0.00016, 0.50016);

        [Test]
        public void TwoCamerasFarApartEachKeepTheirOrigin()
        {
            var origins = new CameraRangeOrigins();
            int snaps = 0;
            for (int frame = 0; frame < 10; frame++)
            {
                if (origins.For(1).Update(NearA)) snaps++;
                if (origins.For(2).Update(NearB)) snaps++;
            }
            Assert.That(snaps, Is.EqualTo(2), "re-snaps in 10 frames of two cameras (one each, the first time)");
            Assert.That(origins.For(1).Origin, Is.EqualTo(RangeOrigin.For(NearA)));
            Assert.That(origins.For(2).Origin, Is.EqualTo(RangeOrigin.For(NearB)));
        }

        [Test]
        public void AWalkReSnapsOnlyPastTheDrift()
        {
            var tracker = new RangeOriginTracker();
            Assert.That(tracker.Update(NearA), Is.True, "first snap");
            Assert.That(tracker.Update(RangeAt(0.30 + 7 * 0.00016)), Is.False, "7 widths away: kept");
            Assert.That(tracker.Update(RangeAt(0.30 + 9 * 0.00016)), Is.True, "9 widths away: re-snapped");
        }

        /// <summary>
        /// What the renderer does with its range every frame (track the origin, encode <c>_Range</c>)
        /// allocates nothing: a constant cost of the measurement cancels between 1,000 and 3,000 frames.
        /// </summary>
        [Test]
        public void TrackingAndEncodingTheRangeAllocatesNothing()
        {
            var tracker = new RangeOriginTracker();
            long[] bytes = new long[2];
            for (int run = 0; run < 2; run++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int k = 0; k < 1000 + 2000 * run; k++)
                {
                    TerrainRange r = RangeAt(0.30 + 1e-6 * (k % 10));
                    tracker.Update(r);
                    RangeMapping.EncodeRange(r, tracker.Origin, out Float4 _, out Float4 _);
                }
                bytes[run] = GC.GetAllocatedBytesForCurrentThread() - before;
            }
            Assert.That(bytes[1] - bytes[0], Is.EqualTo(0), $"bytes allocated by 2,000 more frames ({bytes[0]} by the first 1,000)");
        }

        [Test]
        public void ManyCamerasAreForgottenNotHeld()
        {
            var origins = new CameraRangeOrigins();
            RangeOriginTracker first = origins.For(0);
            for (int id = 1; id <= CameraRangeOrigins.MaxCameras; id++) origins.For(id);
            Assert.That(origins.For(0), Is.Not.SameAs(first), "forgotten past MaxCameras");
        }
    }
}
