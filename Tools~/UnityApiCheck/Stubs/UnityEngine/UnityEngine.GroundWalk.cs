// STUB members used by the Walk on the terrain sample (Samples~/GroundWalk: a Rigidbody walker and
// rolling spheres; issue 28), in a file of their own so other stub edits merge cleanly. Same rules as
// UnityEngine.cs: written from the 2022.3 Scripting Reference (SR:<Page>) and checked against
// UnityCsReference 2022.3 (Modules/Physics/ScriptBindings/Dynamics.bindings.cs: Rigidbody is a
// `public partial class Rigidbody : UnityEngine.Component`, not sealed, its members extern get/set
// properties; Modules/Physics/Managed/Dynamics.cs: RigidbodyInterpolation; Runtime/Export/BaseClass.cs:
// PrimitiveType; Runtime/Export/Scripting/GameObject.bindings.cs: the static CreatePrimitive).
#pragma warning disable CS1591

namespace UnityEngine
{
    // SR:Rigidbody
    public partial class Rigidbody : Component
    {
        public Vector3 velocity { get; set; }                                         // SR:Rigidbody-velocity
        public Vector3 angularVelocity { get; set; }                                  // SR:Rigidbody-angularVelocity
        public float mass { get; set; }                                               // SR:Rigidbody-mass
        public bool isKinematic { get; set; }                                         // SR:Rigidbody-isKinematic
        public bool freezeRotation { get; set; }                                      // SR:Rigidbody-freezeRotation
        public Vector3 position { get; set; }                                         // SR:Rigidbody-position
        public RigidbodyInterpolation interpolation { get; set; }                     // SR:Rigidbody-interpolation
    }

    public enum RigidbodyInterpolation { None = 0, Interpolate = 1, Extrapolate = 2 } // SR:RigidbodyInterpolation

    public enum PrimitiveType { Sphere = 0, Capsule = 1, Cylinder = 2, Cube = 3, Plane = 4, Quad = 5 } // SR:PrimitiveType

    public sealed partial class GameObject                                           // SR:GameObject
    {
        public static GameObject CreatePrimitive(PrimitiveType type) => null;        // SR:GameObject.CreatePrimitive
    }
}

namespace UnityEngine
{
    // The components GameObject.CreatePrimitive(Sphere) adds, named by the Walk sample so that a build
    // keeps them. UnityCsReference 2022.3: Runtime/Export/Graphics/GraphicsComponents.bindings.cs:122
    // (`public sealed partial class MeshFilter : Component`), GraphicsRenderers.bindings.cs:21, :415
    // (`public partial class Renderer : Component`, `public partial class MeshRenderer : Renderer`),
    // Modules/Physics/ScriptBindings/Dynamics.bindings.cs:424 (`public class SphereCollider : Collider`).
    public sealed partial class MeshFilter : Component { }                            // SR:MeshFilter
    public partial class Renderer : Component { }                                     // SR:Renderer
    public partial class MeshRenderer : Renderer { }                                  // SR:MeshRenderer
    public class SphereCollider : Collider { }                                        // SR:SphereCollider
}
