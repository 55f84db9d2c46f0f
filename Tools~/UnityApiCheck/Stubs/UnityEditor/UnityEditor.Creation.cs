// Stubs for GameObject > 3D Object > Gregory Terrain (issue 40), each as Unity 2022.3 declares it
// (UnityCsReference 2022.3: Editor/Mono/MenuCommand.cs, Editor/Mono/ObjectFactory.bindings.cs).
using UnityEngine;

namespace UnityEditor
{
    public sealed class MenuCommand                                                            // SR:MenuCommand
    {
        public Object context;                                                                 // SR:MenuCommand-context
        public int userData;                                                                   // SR:MenuCommand-userData
        public MenuCommand(Object inContext, int inUserData) { context = inContext; userData = inUserData; } // SR:MenuCommand-ctor
        public MenuCommand(Object inContext) { context = inContext; }                          // SR:MenuCommand-ctor
    }

    public static class ObjectFactory                                                          // SR:ObjectFactory
    {
        public static void PlaceGameObject(GameObject go, GameObject parent = null) { }        // SR:ObjectFactory.PlaceGameObject
    }
}
