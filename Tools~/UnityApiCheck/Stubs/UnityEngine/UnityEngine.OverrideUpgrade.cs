// STUB members for the upgrade of old prefab overrides (FlatSettingsOverrideUpgrader), in a file of
// their own so other stub edits merge cleanly. From the 2022.3 Scripting Reference (SR:<Page>),
// checked against UnityCsReference 2022.3 (Runtime/Export/SceneManager/Scene.cs,
// Runtime/Export/Scripting/GameObject.bindings.cs:135).
#pragma warning disable CS1591

namespace UnityEngine
{
    public sealed partial class GameObject
    {
        public T[] GetComponentsInChildren<T>(bool includeInactive) => null;          // SR:GameObject.GetComponentsInChildren
    }
}

namespace UnityEngine.SceneManagement
{
    public partial struct Scene
    {
        public bool isLoaded => false;                                                // SR:SceneManagement.Scene-isLoaded (get only)
        public bool isDirty => false;                                                 // SR:SceneManagement.Scene-isDirty (get only; Scene.cs:64)
        public GameObject[] GetRootGameObjects() => null;                             // SR:SceneManagement.Scene.GetRootGameObjects
    }
}
