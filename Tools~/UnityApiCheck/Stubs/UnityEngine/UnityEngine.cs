// A STUB of the UnityEngine API members the package's Runtime, Editor and Samples~ code uses, written
// by hand from Unity's Scripting Reference (2022.3; the page of each member is named beside it as
// SR:<Page>, meaning https://docs.unity3d.com/2022.3/Documentation/ScriptReference/<Page>.html).
// It is NOT Unity's assembly: only the signatures matter, every body is empty. Where the docs and the
// shipped assembly differ the difference is written down (RenderParams is passed `in`, see Graphics).
#pragma warning disable CS0067, CS1591, CS0626
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    // SR:Object
    public partial class Object                                                       // SR:Object
    {
        public string name { get => null; set { } }                                  // SR:Object-name
        public static implicit operator bool(Object o) => !ReferenceEquals(o, null);  // SR:Object-operator_Object
        public static bool operator ==(Object x, Object y) => ReferenceEquals(x, y);  // SR:Object-operator_eq
        public static bool operator !=(Object x, Object y) => !ReferenceEquals(x, y); // SR:Object-operator_ne
        public override bool Equals(object other) => ReferenceEquals(this, other);
        public override int GetHashCode() => 0;
        public static void DestroyImmediate(Object obj) { }                           // SR:Object.DestroyImmediate
        public static void DestroyImmediate(Object obj, bool allowDestroyingAssets) { } // SR:Object.DestroyImmediate
        public static T Instantiate<T>(T original) where T : Object => original;     // SR:Object.Instantiate
        public static T[] FindObjectsByType<T>(FindObjectsSortMode sortMode) where T : Object => null; // SR:Object.FindObjectsByType
    }

    public enum FindObjectsSortMode { None = 0, InstanceID = 1 }                       // SR:FindObjectsSortMode

    public class Component : Object                                                   // SR:Component
    {
        public Transform transform => null;                                           // SR:Component-transform
        public GameObject gameObject => null;                                         // SR:Component-gameObject
        public T GetComponent<T>() => default;                                        // SR:Component.GetComponent
        public T[] GetComponents<T>() => null;                                        // SR:Component.GetComponents
    }
    public class Behaviour : Component                                                // SR:Behaviour
    {
        public bool enabled { get; set; }                                             // SR:Behaviour-enabled
        public bool isActiveAndEnabled => false;                                      // SR:Behaviour-isActiveAndEnabled
    }
    public class MonoBehaviour : Behaviour { }                                        // SR:MonoBehaviour
    public partial class ScriptableObject : Object                                    // SR:ScriptableObject
    {
        public static T CreateInstance<T>() where T : ScriptableObject => null;       // SR:ScriptableObject.CreateInstance
    }

    public sealed partial class GameObject : Object                                   // SR:GameObject
    {
        public GameObject(string name) { }                                            // SR:GameObject-ctor
        public Transform transform => null;                                           // SR:GameObject-transform
        public int layer { get; set; }                                                // SR:GameObject-layer
        public T AddComponent<T>() where T : Component => null;                       // SR:GameObject.AddComponent
        public T GetComponent<T>() => default;                                        // SR:GameObject.GetComponent
    }

    public class Transform : Component                                                // SR:Transform
    {
        public Vector3 position { get; set; }                                         // SR:Transform-position
        public Quaternion rotation { get; set; }                                      // SR:Transform-rotation
        public Vector3 localScale { get; set; }                                       // SR:Transform-localScale
        public Vector3 lossyScale => default;                                         // SR:Transform-lossyScale
        public Vector3 forward { get; set; }                                          // SR:Transform-forward
        public bool hasChanged { get; set; }                                          // SR:Transform-hasChanged
        public Matrix4x4 localToWorldMatrix => default;                               // SR:Transform-localToWorldMatrix
        public Matrix4x4 worldToLocalMatrix => default;                               // SR:Transform-worldToLocalMatrix
        public Vector3 TransformPoint(Vector3 position) => default;                   // SR:Transform.TransformPoint
        public Vector3 InverseTransformPoint(Vector3 position) => default;            // SR:Transform.InverseTransformPoint
        public Vector3 InverseTransformDirection(Vector3 direction) => default;       // SR:Transform.InverseTransformDirection
        public void SetPositionAndRotation(Vector3 position, Quaternion rotation) { } // SR:Transform.SetPositionAndRotation
        public void LookAt(Vector3 worldPosition) { }                                 // SR:Transform.LookAt
        public Transform parent { get; set; }                                         // SR:Transform-parent
        public void SetParent(Transform parent, bool worldPositionStays) { }          // SR:Transform.SetParent
    }

    public sealed partial class Camera : Behaviour                                    // SR:Camera (sealed partial in 2022.3)
    {
        public static Camera main => null;                                            // SR:Camera-main
        public Ray ScreenPointToRay(Vector3 pos) => default;                          // SR:Camera.ScreenPointToRay
        public float fieldOfView { get; set; }                                        // SR:Camera-fieldOfView
        public float nearClipPlane { get; set; }                                      // SR:Camera-nearClipPlane
        public float farClipPlane { get; set; }                                       // SR:Camera-farClipPlane
        public Matrix4x4 projectionMatrix { get; set; }                               // SR:Camera-projectionMatrix
        public Matrix4x4 worldToCameraMatrix { get; set; }                            // SR:Camera-worldToCameraMatrix
        public int pixelWidth => 0;                                                   // SR:Camera-pixelWidth (read only)
        public int pixelHeight => 0;                                                  // SR:Camera-pixelHeight (read only)
    }

    public sealed class GL                                                            // SR:GL
    {
        public static Matrix4x4 GetGPUProjectionMatrix(Matrix4x4 proj, bool renderIntoTexture) => proj; // SR:GL.GetGPUProjectionMatrix
    }

    public class Debug                                                                // SR:Debug (a plain class in 2022.3, not static)
    {
        public static void Log(object message, Object context) { }                    // SR:Debug.Log
        public static void LogWarning(object message, Object context) { }             // SR:Debug.LogWarning
        public static void LogError(object message, Object context) { }               // SR:Debug.LogError
        public static void LogError(object message) { }                               // SR:Debug.LogError
        public static void LogException(System.Exception exception) { }               // SR:Debug.LogException
    }

    public class Application { public static bool isPlaying => false; }              // SR:Application-isPlaying (plain class)
    public enum RuntimePlatform { OSXEditor = 0, WindowsEditor = 7, LinuxEditor = 16 } // SR:RuntimePlatform (the editor values; Runtime/Export/BaseClass.cs:47 in 2022.3)
    public enum LogType { Error = 0, Assert = 1, Warning = 2, Log = 3, Exception = 4 } // SR:LogType (Runtime/Export/BaseClass.cs:256 in 2022.3)
    public class Time { public static float deltaTime => 0f; public static float time => 0f; public static int frameCount => 0; } // SR:Time-deltaTime, SR:Time-time, SR:Time-frameCount (plain class)

    public struct Mathf                                                               // SR:Mathf (a struct in 2022.3)
    {
        public const float Deg2Rad = 0.017453292f;                                    // SR:Mathf.Deg2Rad
        public const float PI = 3.14159274f;                                          // SR:Mathf.PI
        public static float Clamp(float value, float min, float max) => value;        // SR:Mathf.Clamp
        public static float Log(float f, float p) => f;                               // SR:Mathf.Log
        public static int Clamp(int value, int min, int max) => value;                // SR:Mathf.Clamp
        public static int RoundToInt(float f) => (int)f;                              // SR:Mathf.RoundToInt
        public static float Clamp01(float value) => value;                            // SR:Mathf.Clamp01
        public static float Abs(float f) => f;                                        // SR:Mathf.Abs
        public static float Max(float a, float b) => a;                               // SR:Mathf.Max
        public static int Max(int a, int b) => a;                                     // SR:Mathf.Max
        public static float Min(float a, float b) => a;                               // SR:Mathf.Min
        public static float Tan(float f) => f;                                        // SR:Mathf.Tan
        public static float Sin(float f) => f;                                        // SR:Mathf.Sin
        public static float Cos(float f) => f;                                        // SR:Mathf.Cos
        public static float Lerp(float a, float b, float t) => a;                     // SR:Mathf.Lerp
        public static float Repeat(float t, float length) => t;                       // SR:Mathf.Repeat
        public const float Rad2Deg = 57.29578f;                                       // SR:Mathf.Rad2Deg
        public static float Atan2(float y, float x) => y;                             // SR:Mathf.Atan2
    }

    public struct Vector2                                                             // SR:Vector2
    {
        public float x, y;                                                                // SR:Vector2-x, SR:Vector2-y
        public Vector2(float x, float y) { this.x = x; this.y = y; }                      // SR:Vector2-ctor
        public static Vector2 zero => default;                                        // SR:Vector2-zero
        public float sqrMagnitude => 0f;                                              // SR:Vector2-sqrMagnitude
        public void Normalize() { }                                                   // SR:Vector2.Normalize
        public static Vector2 operator *(Vector2 a, float d) => a;                    // SR:Vector2-operator_multiply
        public static bool operator ==(Vector2 l, Vector2 r) => true;                 // SR:Vector2-operator_eq
        public static bool operator !=(Vector2 l, Vector2 r) => false;                // SR:Vector2-operator_ne
        public override bool Equals(object o) => false;
        public override int GetHashCode() => 0;
    }

    public struct Vector2Int                                                          // SR:Vector2Int
    {
        public int x { get; set; }                                                        // SR:Vector2Int-x
        public int y { get; set; }                                                        // SR:Vector2Int-y
        public Vector2Int(int x, int y) { this.x = x; this.y = y; }                       // SR:Vector2Int-ctor
    }

    public struct Vector3                                                             // SR:Vector3
    {
        public float x, y, z;                                                             // SR:Vector3-x, SR:Vector3-y, SR:Vector3-z
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; } // SR:Vector3-ctor
        public static Vector3 zero => default;                                        // SR:Vector3-zero
        public static Vector3 one => default;                                         // SR:Vector3-one
        public static Vector3 forward => default;                                     // SR:Vector3-forward
        public static Vector3 up => default;                                          // SR:Vector3-up
        public static Vector3 operator +(Vector3 a, Vector3 b) => a;                  // SR:Vector3-operator_add
        public static Vector3 operator -(Vector3 a, Vector3 b) => a;                  // SR:Vector3-operator_subtract
        public static Vector3 operator *(Vector3 a, float d) => a;                    // SR:Vector3-operator_multiply
        public static Vector3 operator *(float d, Vector3 a) => a;                    // SR:Vector3-operator_multiply
        public static bool operator ==(Vector3 l, Vector3 r) => true;                 // SR:Vector3-operator_eq
        public static bool operator !=(Vector3 l, Vector3 r) => false;                // SR:Vector3-operator_ne
        public override bool Equals(object o) => false;
        public override int GetHashCode() => 0;
    }

    public struct Vector4                                                             // SR:Vector4
    {
        public float x, y, z, w;                                                          // SR:Vector4-x (y, z, w)
        public Vector4(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; } // SR:Vector4-ctor
    }

    public struct Quaternion                                                          // SR:Quaternion
    {
        public static Quaternion identity => default;                                 // SR:Quaternion-identity
        public static Quaternion Euler(float x, float y, float z) => default;         // SR:Quaternion.Euler
        public static Vector3 operator *(Quaternion rotation, Vector3 point) => point; // SR:Quaternion-operator_multiply
        public static bool operator ==(Quaternion lhs, Quaternion rhs) => true;       // SR:Quaternion-operator_eq
        public static bool operator !=(Quaternion lhs, Quaternion rhs) => false;      // SR:Quaternion-operator_ne
        public override bool Equals(object other) => false;
        public override int GetHashCode() => 0;
    }

    public struct Matrix4x4                                                           // SR:Matrix4x4
    {
        public float m00, m01, m02, m03, m10, m11, m12, m13, m20, m21, m22, m23, m30, m31, m32, m33; // SR:Matrix4x4-m00 (and m01..m33)
        public Vector3 MultiplyPoint3x4(Vector3 point) => point;                      // SR:Matrix4x4.MultiplyPoint3x4
        public static Matrix4x4 identity => default;                                  // SR:Matrix4x4-identity
        public static Matrix4x4 operator *(Matrix4x4 lhs, Matrix4x4 rhs) => lhs;      // SR:Matrix4x4-operator_multiply
    }

    public struct Color                                                               // SR:Color
    {
        public float r, g, b, a;                                                          // SR:Color-r, SR:Color-g, SR:Color-b, SR:Color-a
        public Color(float r, float g, float b) { this.r = r; this.g = g; this.b = b; a = 1f; } // SR:Color-ctor
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; } // SR:Color-ctor
        public Color linear => this;                                                  // SR:Color-linear
        public float grayscale => 0f;                                                 // SR:Color-grayscale
        public static Color white => default;                                         // SR:Color-white
        public static Color yellow => default;                                        // SR:Color-yellow
        public static Color cyan => default;                                          // SR:Color-cyan
        public static Color red => default;                                           // SR:Color-red
        public static Color green => default;                                         // SR:Color-green
    }

    public struct Bounds                                                              // SR:Bounds
    {
        public Bounds(Vector3 center, Vector3 size) { }                               // SR:Bounds-ctor
        public void Encapsulate(Bounds bounds) { }                                    // SR:Bounds.Encapsulate
    }

    public class Texture : Object                                                     // SR:Texture
    {
        public virtual int width { get => 0; set { } }                                // SR:Texture-width
        public virtual int height { get => 0; set { } }                               // SR:Texture-height
        public virtual bool isReadable => false;                                      // SR:Texture-isReadable
    }
    public sealed class Texture2D : Texture                                           // SR:Texture2D
    {
        public Color[] GetPixels() => null;                                           // SR:Texture2D.GetPixels
        public Texture2D(int width, int height, TextureFormat textureFormat, bool mipChain) { } // SR:Texture2D-ctor
        public TextureFormat format => default;                                       // SR:Texture2D-format (get only)
        public byte[] GetRawTextureData() => null;                                    // SR:Texture2D.GetRawTextureData
        public void LoadRawTextureData(byte[] data) { }                               // SR:Texture2D.LoadRawTextureData
        public void Apply() { }                                                       // SR:Texture2D.Apply
    }
    // SR:TextureFormat (the members the package names; values as in Unity's GraphicsEnums.cs)
    public enum TextureFormat { Alpha8 = 1, RGBA32 = 4, R16 = 9, RHalf = 15, RGBAHalf = 17, RFloat = 18, RGBAFloat = 20, R8 = 63, RGBA64 = 74 }
    public sealed class Terrain : Behaviour                                           // SR:Terrain
    {
        public TerrainData terrainData { get; set; }                                  // SR:Terrain-terrainData
    }
    public sealed class TerrainData : Object                                          // SR:TerrainData
    {
        public int heightmapResolution { get; set; }                                  // SR:TerrainData-heightmapResolution
        public Vector3 size { get; set; }                                             // SR:TerrainData-size
        public float[,] GetHeights(int xBase, int yBase, int width, int height) => null; // SR:TerrainData.GetHeights
    }
    public struct Rect                                                                // SR:Rect (a partial struct in 2022.3; the members used)
    {
        public Rect(float x, float y, float width, float height) { }                  // SR:Rect-ctor
        public float x { get => 0f; set { } }                                         // SR:Rect-x
        public float y { get => 0f; set { } }                                         // SR:Rect-y
        public float width { get => 0f; set { } }                                     // SR:Rect-width
        public float height { get => 0f; set { } }                                    // SR:Rect-height
    }
    // Runtime/Export/Serialization/Serialization.cs in 2022.3: Unity calls these around (de)serializing the object.
    public interface ISerializationCallbackReceiver                                   // SR:ISerializationCallbackReceiver
    {
        void OnBeforeSerialize();                                                     // SR:ISerializationCallbackReceiver.OnBeforeSerialize
        void OnAfterDeserialize();                                                    // SR:ISerializationCallbackReceiver.OnAfterDeserialize
    }
    public class GUILayoutUtility                                                     // SR:GUILayoutUtility
    {
        public static Rect GetRect(float minWidth, float maxWidth, float minHeight, float maxHeight) => default; // SR:GUILayoutUtility.GetRect
    }

    public sealed partial class Shader : Object                                       // SR:Shader
    {
        public static int PropertyToID(string name) => 0;                             // SR:Shader.PropertyToID
        public static Shader Find(string name) => null;                               // SR:Shader.Find
    }

    public partial class Material : Object                                            // SR:Material
    {
        public Material(Shader shader) { }                                            // SR:Material-ctor
        public Shader shader { get; set; }                                            // SR:Material-shader
        public string GetTag(string tag, bool searchFallbacks, string defaultValue) => defaultValue; // SR:Material.GetTag
        public bool IsKeywordEnabled(string keyword) => false;                        // SR:Material.IsKeywordEnabled
        public void EnableKeyword(string keyword) { }                                 // SR:Material.EnableKeyword
        public void DisableKeyword(string keyword) { }                                // SR:Material.DisableKeyword
        public void SetVector(int nameID, Vector4 value) { }                          // SR:Material.SetVector
        public void SetFloat(string name, float value) { }                            // SR:Material.SetFloat
        public void SetBuffer(int nameID, ComputeBuffer value) { }                    // SR:Material.SetBuffer
        public void SetBuffer(int nameID, GraphicsBuffer value) { }                   // SR:Material.SetBuffer
    }

    public sealed class ComputeBuffer : IDisposable                                   // SR:ComputeBuffer
    {
        public ComputeBuffer(int count, int stride) { }                               // SR:ComputeBuffer-ctor
        public int count => 0;                                                        // SR:ComputeBuffer-count
        public int stride => 0;                                                       // SR:ComputeBuffer-stride
        public void SetData(Array data) { }                                           // SR:ComputeBuffer.SetData
        public void GetData(Array data) { }                                           // SR:ComputeBuffer.GetData
        public void Release() { }                                                     // SR:ComputeBuffer.Release
        public bool IsValid() => false;                                               // SR:ComputeBuffer.IsValid
        public void Dispose() { }                                                     // SR:ComputeBuffer.Dispose
    }

    public sealed class ComputeShader : Object                                        // SR:ComputeShader
    {
        public int FindKernel(string name) => 0;                                      // SR:ComputeShader.FindKernel
        public bool IsSupported(int kernelIndex) => false;                           // SR:ComputeShader.IsSupported (ComputeShader.bindings.cs:109)
        public bool HasKernel(string name) => false;                                  // SR:ComputeShader.HasKernel
        public void SetBuffer(int kernelIndex, int nameID, ComputeBuffer buffer) { }  // SR:ComputeShader.SetBuffer
        public void SetBuffer(int kernelIndex, int nameID, GraphicsBuffer buffer) { } // SR:ComputeShader.SetBuffer
        public void SetVector(int nameID, Vector4 val) { }                            // SR:ComputeShader.SetVector
        public void SetMatrix(int nameID, Matrix4x4 val) { }                          // SR:ComputeShader.SetMatrix
        public void SetVectorArray(int nameID, Vector4[] values) { }                  // SR:ComputeShader.SetVectorArray
        public void EnableKeyword(string keyword) { }                                 // SR:ComputeShader.EnableKeyword (2020.2+)
        public void DisableKeyword(string keyword) { }                                // SR:ComputeShader.DisableKeyword (2020.2+)
        public void Dispatch(int kernelIndex, int threadGroupsX, int threadGroupsY, int threadGroupsZ) { } // SR:ComputeShader.Dispatch
    }

    public sealed partial class MaterialPropertyBlock                                 // SR:MaterialPropertyBlock
    {
        public void SetVector(int nameID, Vector4 value) { }                          // SR:MaterialPropertyBlock.SetVector
        public void SetVectorArray(int nameID, Vector4[] values) { }                  // SR:MaterialPropertyBlock.SetVectorArray
        public void SetMatrix(int nameID, Matrix4x4 value) { }                        // SR:MaterialPropertyBlock.SetMatrix
        public void SetBuffer(int nameID, GraphicsBuffer value) { }                   // SR:MaterialPropertyBlock.SetBuffer
        public void Clear() { }                                                       // SR:MaterialPropertyBlock.Clear
    }

    public sealed class GraphicsBuffer : IDisposable                                  // SR:GraphicsBuffer
    {
        [Flags]
        public enum Target { Vertex = 1, Index = 2, CopySource = 4, CopyDestination = 8, Structured = 16, Raw = 32, Append = 64, Counter = 128, IndirectArguments = 256, Constant = 512 } // SR:GraphicsBuffer.Target
        public GraphicsBuffer(Target target, int count, int stride) { }               // SR:GraphicsBuffer-ctor
        public int count => 0;                                                        // SR:GraphicsBuffer-count
        public int stride => 0;                                                       // SR:GraphicsBuffer-stride
        public void SetData(Array data) { }                                           // SR:GraphicsBuffer.SetData
        public void SetData(Array data, int managedBufferStartIndex, int graphicsBufferStartIndex, int count) { } // SR:GraphicsBuffer.SetData
        public void Release() { }                                                     // SR:GraphicsBuffer.Release
        public bool IsValid() => false;                                               // SR:GraphicsBuffer.IsValid
        public void Dispose() { }                                                     // SR:GraphicsBuffer.Dispose
    }

    public enum MeshTopology { Triangles = 0, Quads = 2, Lines = 3, LineStrip = 4, Points = 5 } // SR:MeshTopology

    // SR:RenderParams. Properties with get/set; the constructor takes the material. Its defaults
    // (verified in the 2022.3 page's property list): no shadows cast, none received.
    public struct RenderParams
    {
        public RenderParams(Material mat) { }                                             // SR:RenderParams-ctor
        public Material material { get => null; set { } }                                 // SR:RenderParams-material
        public Bounds worldBounds { get => default; set { } }                             // SR:RenderParams-worldBounds
        public MaterialPropertyBlock matProps { get => null; set { } }                    // SR:RenderParams-matProps
        public Rendering.ShadowCastingMode shadowCastingMode { get => default; set { } }  // SR:RenderParams-shadowCastingMode
        public bool receiveShadows { get => false; set { } }                              // SR:RenderParams-receiveShadows
        public int layer { get => 0; set { } }                                            // SR:RenderParams-layer
        public Camera camera { get => null; set { } }                                     // SR:RenderParams-camera
    }

    public class Graphics                                                             // SR:Graphics (plain class)
    {
        // SR:Graphics.RenderPrimitives. The page prints `ref RenderParams`; Unity's shipped assembly
        // (2022.2 and later, as decompiled listings show) declares `in`, which is why callers pass the
        // struct without a modifier. A `ref` here would reject that call; `in` accepts it.
        public static void RenderPrimitives(in RenderParams rparams, MeshTopology topology, int vertexCount, int instanceCount = 1) { }
        // SR:Graphics.RenderPrimitivesIndexed (same note on in/ref).
        public static void RenderPrimitivesIndexed(in RenderParams rparams, MeshTopology topology, GraphicsBuffer indexBuffer, int indexCount, int startIndex = 0, int instanceCount = 1) { }
    }

    public sealed class SystemInfo                                                    // SR:SystemInfo
    {
        public static bool supportsTessellationShaders => false;                      // SR:SystemInfo-supportsTessellationShaders
        public static bool supportsComputeShaders => false;                           // SR:SystemInfo-supportsComputeShaders
        public static bool supportsAsyncGPUReadback => false;                         // SR:SystemInfo-supportsAsyncGPUReadback
        public static long maxGraphicsBufferSize => 0;                                // SR:SystemInfo-maxGraphicsBufferSize
        public static bool supportsInstancing => false;                               // SR:SystemInfo-supportsInstancing
    }

    public sealed class Gizmos                                                        // SR:Gizmos
    {
        public static Color color { get; set; }                                       // SR:Gizmos-color
        public static Matrix4x4 matrix { get; set; }                                  // SR:Gizmos-matrix
    }

#if ENABLE_LEGACY_INPUT_MANAGER
    public class Input                                                                // SR:Input (legacy Input Manager; plain class)
    {
        public static Vector2 mouseScrollDelta => default;                            // SR:Input-mouseScrollDelta
        public static float GetAxis(string axisName) => 0f;                           // SR:Input.GetAxis
        public static bool GetButtonDown(string buttonName) => false;                 // SR:Input.GetButtonDown
        public static bool GetMouseButton(int button) => false;                       // SR:Input.GetMouseButton
    }
#endif

    // ---- attributes ----------------------------------------------------------------------------
    public sealed class ExecuteAlways : Attribute { }                                                                  // SR:ExecuteAlways (no AttributeUsage in 2022.3: any target)
    [AttributeUsage(AttributeTargets.Class, Inherited = false)] public sealed class DisallowMultipleComponent : Attribute { } // SR:DisallowMultipleComponent
    public sealed class AddComponentMenu : Attribute { public AddComponentMenu(string menuName) { } }                 // SR:AddComponentMenu (no AttributeUsage in 2022.3)
    [AttributeUsage(AttributeTargets.Class)] public class DefaultExecutionOrder : Attribute { public DefaultExecutionOrder(int order) { } } // SR:DefaultExecutionOrder (not sealed)
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)] public sealed class RequireComponent : Attribute { public RequireComponent(Type requiredComponent) { } } // SR:RequireComponent
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false, Inherited = false)]
    public sealed class CreateAssetMenuAttribute : Attribute                                                           // SR:CreateAssetMenuAttribute
    {
        public string menuName { get; set; }                                              // SR:CreateAssetMenuAttribute-menuName
        public string fileName { get; set; }                                              // SR:CreateAssetMenuAttribute-fileName
        public int order { get; set; }                                                    // SR:CreateAssetMenuAttribute-order
    }
    public sealed class SerializeField : Attribute { }                                                                 // SR:SerializeField (no AttributeUsage in 2022.3)
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)] public abstract class PropertyAttribute : Attribute { } // SR:PropertyAttribute
    [AttributeUsage(AttributeTargets.All, Inherited = true, AllowMultiple = false)] public class TooltipAttribute : PropertyAttribute { public TooltipAttribute(string tooltip) { } } // SR:TooltipAttribute
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)] public sealed class RangeAttribute : PropertyAttribute { public RangeAttribute(float min, float max) { } } // SR:RangeAttribute
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)] public sealed class MinAttribute : PropertyAttribute { public MinAttribute(float min) { } } // SR:MinAttribute
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)] public sealed class TextAreaAttribute : PropertyAttribute { public TextAreaAttribute() { } public TextAreaAttribute(int minLines, int maxLines) { } } // SR:TextAreaAttribute
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = true)] public class HeaderAttribute : PropertyAttribute { public HeaderAttribute(string header) { } } // SR:HeaderAttribute
    public sealed class HideInInspector : Attribute { }                                                                // SR:HideInInspector (no AttributeUsage in 2022.3)
}

namespace UnityEngine.Rendering
{
    public enum ShadowCastingMode { Off = 0, On = 1, TwoSided = 2, ShadowsOnly = 3 } // SR:Rendering.ShadowCastingMode

    public struct AsyncGPUReadbackRequest                                             // SR:Rendering.AsyncGPUReadbackRequest
    {
        public bool hasError => false;                                                // SR:Rendering.AsyncGPUReadbackRequest-hasError
        public Unity.Collections.NativeArray<T> GetData<T>(int layer = 0) where T : struct => default; // SR:Rendering.AsyncGPUReadbackRequest.GetData
    }

    public static class AsyncGPUReadback                                              // SR:Rendering.AsyncGPUReadback
    {
        // SR:Rendering.AsyncGPUReadback.Request (the GraphicsBuffer, size, offset overload; the callback runs on the main thread once the data is there)
        public static AsyncGPUReadbackRequest Request(GraphicsBuffer src, int size, int offset, Action<AsyncGPUReadbackRequest> callback = null) => default;
    }
}

namespace Unity.Collections
{
    public struct NativeArray<T> where T : struct                                    // SR:Unity.Collections.NativeArray_1
    {
        public T this[int index] { get => default; set { } }                          // SR:Unity.Collections.NativeArray_1-Item
    }
}

namespace UnityEngine
{
    // ---- IMGUI types used by the editor code ----------------------------------------------------
    public class GUIContent                                                           // SR:GUIContent
    {
        public GUIContent(string text) { }                                            // SR:GUIContent-ctor
        public GUIContent(string text, string tooltip) { }                            // SR:GUIContent-ctor
        public string text { get => null; set { } }                                   // SR:GUIContent-text
    }
    public sealed class GUILayoutOption { }                                           // SR:GUILayoutOption
    public sealed class GUIStyle { }                                                  // SR:GUIStyle (passed through only)
    public class GUILayout                                                            // SR:GUILayout
    {
        public static bool Button(GUIContent content, params GUILayoutOption[] options) => false; // SR:GUILayout.Button
    }
    public enum EventType { MouseDown = 0, MouseUp = 1, MouseMove = 2, MouseDrag = 3, KeyDown = 4, KeyUp = 5, Repaint = 7, Layout = 8 } // SR:EventType
    public enum KeyCode { LeftBracket = 91, RightBracket = 93, B = 98, G = 103, I = 105, U = 117 }                                 // SR:KeyCode (values: ASCII, as listed)
    public sealed partial class Event                                                 // SR:Event (sealed partial in 2022.3)
    {
        public static Event current { get => null; set { } }                          // SR:Event-current
        public EventType type { get; set; }                                           // SR:Event-type
    }
}
