using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace GregoryTerrain.Tests
{
    /// <summary>The snow simulator's field sources, run in Unity (Edit Mode: nothing is simulated).</summary>
    public class SnowSimulatorTests
    {
        GameObject _go;
        GraphicsBuffer _buffer;

        [SetUp] public void SetUp() => _go = new GameObject("snow");

        [TearDown]
        public void TearDown()
        {
            _buffer?.Release();
            Object.DestroyImmediate(_go);
        }

        [Test]
        public void NewResolutionDropsAFieldBufferOfTheOldOne()
        {
            var snow = _go.AddComponent<SnowSimulator>();
            SnowSettings s = snow.Settings;
            s.resolution = 64;
            snow.Settings = s;
            _buffer = new GraphicsBuffer(GraphicsBuffer.Target.Structured, 64 * 64, 16);
            snow.SetFieldBuffer(_buffer, 1);
            Assert.That(snow.UsesFieldBuffer, Is.True);

            s.resolution = 128;   // the kernels would now read 128^2 float4 from a 64^2 buffer
            snow.Settings = s;
            Assert.That(snow.UsesFieldBuffer, Is.False, "a 64^2 field buffer kept after the map became 128^2");
            Assert.Throws<System.ArgumentException>(() => snow.SetFieldBuffer(_buffer, 2), "the old buffer is refused for the new resolution");
        }

#if UNITY_EDITOR
        [Test]
        public void AnInvalidInspectorEditIsLoggedAndNotUsed()
        {
            var snow = _go.AddComponent<SnowSimulator>();
            SnowSettings s = snow.Settings;
            s.resolution = 128;
            snow.Settings = s;
            using var so = new UnityEditor.SerializedObject(snow);
            so.FindProperty("settings.resolution").intValue = 100;
            LogAssert.Expect(LogType.Error, new System.Text.RegularExpressions.Regex(@"snow\.resolution \(100\) must be a power of two"));
            so.ApplyModifiedProperties();   // as the Inspector: Unity calls OnValidate
            Assert.That(snow.MapSize.x, Is.EqualTo(128f), "the last valid resolution stays in use");
        }
#endif

        [Test]
        public void SameResolutionKeepsTheFieldBuffer()
        {
            var snow = _go.AddComponent<SnowSimulator>();
            SnowSettings s = snow.Settings;
            _buffer = new GraphicsBuffer(GraphicsBuffer.Target.Structured, s.resolution * s.resolution, 16);
            snow.SetFieldBuffer(_buffer, 1);
            s.depthCap *= 2f;   // not the resolution
            snow.Settings = s;
            Assert.That(snow.UsesFieldBuffer, Is.True);
        }
    }
}
