// STUB members of UnityEngine used by issue 23's editor side: the samples' lighting script (Samples~/TerrainFlyover/SampleSun.cs),
// the binary grid asset and its undo hook (PreferBinarySerialization, Resources); kept apart from UnityEngine.cs so that changes there merge cleanly. Written from
// the Scripting Reference (SR:<Page> as in UnityEngine.cs) and checked against UnityCsReference 2022.3
// (Runtime/Export/Graphics/GraphicsComponents.bindings.cs, Shaders/Shader.bindings.cs,
// Scripting/UnityEngineObject.bindings.cs, GameObject.bindings.cs, ScriptableObject.bindings.cs).
#pragma warning disable CS1591
using System;

namespace UnityEngine
{
    // HideFlags, Object.hideFlags and Object.Destroy: declared with the runtime side's stubs (UnityEngine.Rendering.cs).

    public partial class ScriptableObject                                            // SR:ScriptableObject
    {
        public static ScriptableObject CreateInstance(Type type) => null;            // SR:ScriptableObject.CreateInstance
    }

    public sealed partial class GameObject                                           // SR:GameObject
    {
        public Component AddComponent(Type componentType) => null;                   // SR:GameObject.AddComponent
        public Component GetComponent(string type) => null;                          // SR:GameObject.GetComponent
    }

    public sealed partial class Shader                                               // SR:Shader
    {
        public static string globalRenderPipeline { get => null; set { } }           // SR:Shader-globalRenderPipeline
    }

    public sealed class Light : Behaviour                                            // SR:Light (sealed partial in 2022.3)
    {
        public float intensity { get; set; }                                         // SR:Light-intensity
    }
}

namespace UnityEngine
{
    // Used by PatchGridAsset (issue 23: grids saved in binary). UnityCsReference 2022.3:
    // Runtime/Export/Serialization/Serialization.cs:35.
    [AttributeUsage(AttributeTargets.Class)] public sealed class PreferBinarySerialization : Attribute { } // SR:PreferBinarySerialization
}

namespace UnityEngine
{
    public sealed class Resources                                                    // SR:Resources
    {
        public static T[] FindObjectsOfTypeAll<T>() where T : Object => null;        // SR:Resources.FindObjectsOfTypeAll
    }
}

namespace UnityEngine.Serialization
{
    // Used by PatchGridWindow (renamed settings). UnityCsReference 2022.3:
    // Runtime/Export/Serialization/FormerlySerializedAsAttribute.cs:12.
    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true, Inherited = false)]
    public class FormerlySerializedAsAttribute : Attribute                           // SR:Serialization.FormerlySerializedAsAttribute
    {
        public FormerlySerializedAsAttribute(string oldName) { this.oldName = oldName; } // SR:Serialization.FormerlySerializedAsAttribute-ctor
        public string oldName { get; }                                               // SR:Serialization.FormerlySerializedAsAttribute-oldName
    }
}
