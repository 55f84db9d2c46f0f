using NUnit.Framework;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// Range controllers in Edit Mode (where the editor's Test Runner runs these): they preview the
    /// range without writing saved state, and the zoom controller never moves a camera the user is
    /// placing unless Place Camera In Edit Mode is on.
    /// </summary>
    public class RangeControllerEditModeTests
    {
        TestTerrain _t;

        [SetUp] public void SetUp() => _t = new TestTerrain();
        [TearDown] public void TearDown() => _t.Dispose();

        [Test]
        public void ZoomControllerPreviewsWithoutSavingOrMovingTheCamera()
        {
            Assume.That(Application.isPlaying, Is.False, "an Edit Mode test");
            GregoryTerrainRenderer r = _t.Renderer("terrain");
            Camera cam = _t.Camera("view");
            var placed = new Vector3(3f, 4f, 5f);
            cam.transform.position = placed;
            Vector4 saved = r.SavedRange;

            var zoom = cam.gameObject.AddComponent<ZoomRangeController>();
            zoom.Target = r;
            zoom.ViewCamera = cam;
            zoom.Zoom(2f, new Vector2(0.5f, 0.5f));   // width 1/4
            zoom.Apply();

            Assert.That(r.Range.Width, Is.EqualTo(0.25).Within(1e-12), "the drawn range follows the controller");
            Assert.That(r.SavedRange, Is.EqualTo(saved), "the renderer's saved range is not written in Edit Mode");
            Assert.That(cam.transform.position, Is.EqualTo(placed), "the camera stays where the user put it");

            zoom.PlaceCameraInEditMode = true;   // asked for: now it moves
            zoom.Apply();
            Assert.That(cam.transform.position, Is.Not.EqualTo(placed));
        }

        [Test]
        public void ZoomAndPanFromCodeInEditModeAreUndoable()
        {
            Assume.That(Application.isPlaying, Is.False, "an Edit Mode test");
            GregoryTerrainRenderer r = _t.Renderer("terrain");
            var zoom = _t.Camera("view").gameObject.AddComponent<ZoomRangeController>();
            zoom.Target = r;
            double before = zoom.Width;
            UnityEditor.Undo.IncrementCurrentGroup();   // each call its own step, as separate user actions are
            zoom.Zoom(2f, new Vector2(0.5f, 0.5f));
            Assert.That(zoom.Width, Is.EqualTo(before / 4.0).Within(1e-12));
            UnityEditor.Undo.PerformUndo();
            Assert.That(zoom.Width, Is.EqualTo(before).Within(1e-12), "Undo restores the zoom level");

            UnityEditor.Undo.IncrementCurrentGroup();
            zoom.Pan(new Vector2(0.25f, 0f));
            zoom.Apply();
            double panned = r.Range.Center.x;   // the drawn range moved
            UnityEditor.Undo.PerformUndo();
            zoom.Apply();
            Assert.That(r.Range.Center.x, Is.Not.EqualTo(panned), "Undo moves the range back");
        }

        [Test]
        public void PlacedCameraFollowsAPitchChange()
        {
            GregoryTerrainRenderer r = _t.Renderer("terrain");
            Camera cam = _t.Camera("view");
            var zoom = cam.gameObject.AddComponent<ZoomRangeController>();
            zoom.Target = r;
            zoom.ViewCamera = cam;
            zoom.PlaceCameraInEditMode = true;
            zoom.Apply();
            Quaternion placed = cam.transform.rotation;
            cam.transform.rotation = Quaternion.identity;   // only the rotation differs from the placement
            zoom.Apply();
            Assert.That(cam.transform.rotation, Is.EqualTo(placed), "the camera is placed again when only its rotation changed");
        }
    }
}
