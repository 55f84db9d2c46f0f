using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The terrain collider keeps physics' view of its patch whole: where it moves its Transform and
    /// swaps its MeshCollider's mesh, it also syncs the move to physics. A new sharedMesh reaches
    /// physics at once, a Transform change (Physics.autoSyncTransforms off, Unity's default since
    /// 2017.2) only before the next simulation step, so queries in between would see the new patch at
    /// the old pose. Only Unity's physics shows the gap; this reads the C#.
    /// </summary>
    [TestFixture]
    public class ColliderSourceTests
    {
        /// <summary>Methods that move the Transform and set sharedMesh without Physics.SyncTransforms() after the move.</summary>
        internal static List<string> UnsyncedSwaps(string code)
        {
            code = Regex.Replace(code, @"//[^\n]*", "");
            var found = new List<string>();
            foreach (Match m in Regex.Matches(code, @"\bvoid\s+(\w+)\s*\([^)]*\)\s*\{"))
            {
                string body = RendererStateSourceTests.Body(code.Substring(m.Index), m.Groups[1].Value) ?? "";
                Match move = Regex.Match(body, @"transform\s*\.\s*(?:SetPositionAndRotation\s*\(|position\s*=|rotation\s*=)");
                if (!move.Success || !Regex.IsMatch(body, @"sharedMesh\s*=")) continue;
                int sync = body.IndexOf("Physics.SyncTransforms()", move.Index);
                if (sync < 0) found.Add(m.Groups[1].Value);
            }
            return found;
        }

        [Test]
        public void TheColliderSyncsItsMoveWithItsNewMesh()
        {
            string code = File.ReadAllText(PackageRoot.Combine("Runtime", "GregoryTerrainCollider.cs"));
            Assert.That(code, Does.Match(@"sharedMesh\s*="), "the collider swaps its mesh");
            Assert.That(UnsyncedSwaps(code), Is.Empty, "mesh swapped and Transform moved without Physics.SyncTransforms()");
        }

        [Test]
        public void SyncCheckRejectsTheUnsyncedSwap()
        {
            string old = "void Swap()\n{\n    transform.SetPositionAndRotation(_pendingPosition, _pendingRotation);\n    _collider.sharedMesh = _meshes[_spare];\n    _stage = Stage.Idle;\n}";
            Assert.That(UnsyncedSwaps(old), Is.EqualTo(new[] { "Swap" }));
            string synced = "void Swap()\n{\n    transform.SetPositionAndRotation(p, r);\n    _collider.sharedMesh = m;\n    Physics.SyncTransforms();\n}";
            Assert.That(UnsyncedSwaps(synced), Is.Empty);
        }
    }
}
