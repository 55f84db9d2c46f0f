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
