// STUB members for the terrain collider and the CPU queries (issue 28), in a file of their own so
// other stub edits merge cleanly. Same rules as UnityEngine.cs: written by hand from the 2022.3
// Scripting Reference (SR:<Page>) and checked against the declarations of Unity's C# reference source
// for 2022.3 (Modules/Physics/ScriptBindings/Dynamics.bindings.cs, Modules/Physics/Managed/Dynamics.cs,
// Runtime/Export/Graphics/Mesh.cs, Runtime/Export/Geometry/Ray.cs): member kinds, static-ness, types.
#pragma warning disable CS0067, CS1591, CS0626
using System;

namespace UnityEngine
{
    // SR:Ray
    public partial struct Ray
    {
        public Vector3 origin { get; set; }                                           // SR:Ray-origin
        public Vector3 direction { get; set; }                                        // SR:Ray-direction
    }

    // SR:Mesh (sealed partial class in the reference source)
    public sealed partial class Mesh : Object
    {
        public Mesh() { }                                                             // SR:Mesh-ctor
        public void SetVertices(Vector3[] inVertices) { }                             // SR:Mesh.SetVertices
        public void SetTriangles(int[] triangles, int submesh) { }                    // SR:Mesh.SetTriangles
        public void RecalculateBounds() { }                                           // SR:Mesh.RecalculateBounds
        public void MarkDynamic() { }                                                 // SR:Mesh.MarkDynamic
    }

    // SR:Collider
    public partial class Collider : Component { }

    // SR:MeshCollider
    public partial class MeshCollider : Collider
    {
        public Mesh sharedMesh { get; set; }                                          // SR:MeshCollider-sharedMesh
        public MeshColliderCookingOptions cookingOptions { get; set; }                // SR:MeshCollider-cookingOptions
    }

    // SR:MeshColliderCookingOptions (InflateConvexMesh = 1 is obsolete as an error and left out)
    [Flags]
    public enum MeshColliderCookingOptions
    {
        None,
        CookForFasterSimulation = 1 << 1,
        EnableMeshCleaning = 1 << 2,
        WeldColocatedVertices = 1 << 3,
        UseFastMidphase = 1 << 4,
    }

    // SR:Physics
    public partial class Physics
    {
        // [ThreadSafe] in the reference source: callable from any thread (SR:Physics.BakeMesh says so too).
        public static void BakeMesh(int meshID, bool convex, MeshColliderCookingOptions cookingOptions) { } // SR:Physics.BakeMesh
        public static void SyncTransforms() { }                                       // SR:Physics.SyncTransforms (Dynamics.bindings.cs:1575 in 2022.3)
    }
}

// The collider's Profiler marker (Runtime/Profiler/ScriptBindings/ProfilerMarker.bindings.cs, 2022.3:
// a struct; Begin/End are [Conditional("ENABLE_PROFILER")], Auto is not).
namespace Unity.Profiling
{
    // SR:Unity.Profiling.ProfilerMarker
    public struct ProfilerMarker
    {
        public ProfilerMarker(string name) { }                                        // SR:Unity.Profiling.ProfilerMarker-ctor
        public AutoScope Auto() => default;                                           // SR:Unity.Profiling.ProfilerMarker.Auto

        // SR:Unity.Profiling.ProfilerMarker.AutoScope
        public struct AutoScope : IDisposable
        {
            public void Dispose() { }                                                 // SR:Unity.Profiling.ProfilerMarker.AutoScope.Dispose
        }
    }
}
