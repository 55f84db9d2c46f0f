// STUB members for drawing per camera and per-renderer shader state (issue 23, runtime half), in a
// file of their own so the editor half's stub edits merge cleanly. Same rules as UnityEngine.cs:
// written by hand from the 2022.3 Scripting Reference (SR:<Page>) and checked against the
// declarations of Unity's C# reference source for 2022.3 (member kinds, static-ness, nesting).
#pragma warning disable CS0067, CS1591, CS0626
using System;

namespace UnityEngine
{
    // SR:HideFlags (values as declared: DontSave and HideAndDontSave are combinations)
    [Flags]
    public enum HideFlags
    {
        None = 0, HideInHierarchy = 1, HideInInspector = 2, DontSaveInEditor = 4, NotEditable = 8,
        DontSaveInBuild = 16, DontUnloadUnusedAsset = 32,
        DontSave = DontSaveInEditor | DontSaveInBuild | DontUnloadUnusedAsset,
        HideAndDontSave = HideInHierarchy | DontSaveInEditor | NotEditable | DontSaveInBuild | DontUnloadUnusedAsset,
    }

    public enum CameraType { Game = 1, SceneView = 2, Preview = 4, VR = 8, Reflection = 16 } // SR:CameraType

    public partial class Object
    {
        public HideFlags hideFlags { get => default; set { } }                        // SR:Object-hideFlags
        public static void Destroy(Object obj) { }                                    // SR:Object.Destroy
        public int GetInstanceID() => 0;                                              // SR:Object.GetInstanceID
    }

    public sealed partial class GameObject
    {
        public SceneManagement.Scene scene => default;                                // SR:GameObject-scene
        public ulong sceneCullingMask => 0;                                           // SR:GameObject-sceneCullingMask (read only)
        public bool activeSelf => false;                                              // SR:GameObject-activeSelf
        public void SetActive(bool value) { }                                         // SR:GameObject.SetActive
    }

    public sealed partial class Camera
    {
        public CameraType cameraType { get; set; }                                    // SR:Camera-cameraType
        public SceneManagement.Scene scene { get; set; }                              // SR:Camera-scene
        public ulong overrideSceneCullingMask { get; set; }                           // SR:Camera-overrideSceneCullingMask
        public delegate void CameraCallback(Camera cam);                              // SR:Camera.CameraCallback (nested)
        public static CameraCallback onPreCull;                                       // SR:Camera-onPreCull (a field, not an event)
        public void Render() { }                                                      // SR:Camera.Render
    }

    public partial class Material
    {
        public Material(Material source) { }                                          // SR:Material-ctor
        public void CopyPropertiesFromMaterial(Material mat) { }                      // SR:Material.CopyPropertiesFromMaterial
        public int ComputeCRC() => 0;                                                 // SR:Material.ComputeCRC
        public string[] shaderKeywords { get => null; set { } }                       // SR:Material-shaderKeywords
        public Vector4 GetVector(int nameID) => default;                              // SR:Material.GetVector
    }

    public sealed partial class MaterialPropertyBlock
    {
        public Vector4 GetVector(int nameID) => default;                              // SR:MaterialPropertyBlock.GetVector
        public Matrix4x4 GetMatrix(int nameID) => default;                            // SR:MaterialPropertyBlock.GetMatrix
        public bool HasMatrix(int nameID) => false;                                   // SR:MaterialPropertyBlock.HasMatrix
        public bool HasBuffer(int nameID) => false;                                   // SR:MaterialPropertyBlock.HasBuffer
        public bool isEmpty => true;                                                  // SR:MaterialPropertyBlock-isEmpty
    }
}

namespace UnityEngine.SceneManagement
{
    public partial struct Scene                                                       // SR:SceneManagement.Scene
    {
        public bool IsValid() => false;                                               // SR:SceneManagement.Scene.IsValid
        public static bool operator ==(Scene lhs, Scene rhs) => true;                 // SR:SceneManagement.Scene-operator_eq
        public static bool operator !=(Scene lhs, Scene rhs) => false;                // SR:SceneManagement.Scene-operator_ne
        public override bool Equals(object other) => other is Scene;                 // SR:SceneManagement.Scene.Equals
        public override int GetHashCode() => 0;                                       // SR:SceneManagement.Scene.GetHashCode
    }
    public class SceneManager                                                         // SR:SceneManagement.SceneManager
    {
        public static void MoveGameObjectToScene(GameObject go, Scene scene) { }      // SR:SceneManagement.SceneManager.MoveGameObjectToScene
        public static Scene GetSceneByPath(string scenePath) => default;              // SR:SceneManagement.SceneManager.GetSceneByPath
    }
}

namespace UnityEngine.Rendering
{
    // SR:Rendering.ScriptableRenderContext (a struct; the package only receives it)
    public struct ScriptableRenderContext : IEquatable<ScriptableRenderContext>
    {
        public bool Equals(ScriptableRenderContext other) => false;                         // SR:Rendering.ScriptableRenderContext.Equals
    }

    public static class RenderPipelineManager                                         // SR:Rendering.RenderPipelineManager
    {
        public static event Action<ScriptableRenderContext, Camera> beginCameraRendering; // SR:Rendering.RenderPipelineManager-beginCameraRendering
    }
}
