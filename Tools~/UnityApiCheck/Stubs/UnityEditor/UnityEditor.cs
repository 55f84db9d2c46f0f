// Filled as the Editor code is written.
namespace UnityEditor
{
    public delegate void AssemblyReloadCallback();                                          // SR:AssemblyReloadEvents.AssemblyReloadCallback
    public static class AssemblyReloadEvents                                                // SR:AssemblyReloadEvents
    {
        public static event AssemblyReloadCallback beforeAssemblyReload;                    // SR:AssemblyReloadEvents-beforeAssemblyReload
    }
}
