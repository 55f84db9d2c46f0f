// A STUB of the Input System package's (com.unity.inputsystem) members the Walk sample reads, written
// from the package's source (Unity-Technologies/InputSystem, Packages/com.unity.inputsystem/InputSystem:
// Devices/Keyboard.cs, Mouse.cs, Pointer.cs, InputDevice.cs; Controls/InputControl.cs, AxisControl.cs,
// ButtonControl.cs, KeyControl.cs, Vector2Control.cs, DeltaControl.cs). Classes are plain (not sealed),
// as there; SR: names the page of the package's API reference. Every body is empty.
#pragma warning disable CS1591

namespace UnityEngine.InputSystem
{
    public abstract class InputControl { }                                            // SR:InputSystem.InputControl
    public abstract class InputControl<TValue> : InputControl where TValue : struct   // SR:InputSystem.InputControl-1
    {
        public TValue ReadValue() => default;                                         // SR:InputSystem.InputControl-1.ReadValue
    }
    public class InputDevice : InputControl { }                                       // SR:InputSystem.InputDevice

    public class Keyboard : InputDevice                                               // SR:InputSystem.Keyboard
    {
        public static Keyboard current { get; private set; }                          // SR:InputSystem.Keyboard-current
        public Controls.KeyControl spaceKey => null;                                  // SR:InputSystem.Keyboard-spaceKey
        public Controls.KeyControl aKey => null;                                      // SR:InputSystem.Keyboard-aKey
        public Controls.KeyControl dKey => null;                                      // SR:InputSystem.Keyboard-dKey
        public Controls.KeyControl sKey => null;                                      // SR:InputSystem.Keyboard-sKey
        public Controls.KeyControl wKey => null;                                      // SR:InputSystem.Keyboard-wKey
        public Controls.KeyControl leftArrowKey => null;                              // SR:InputSystem.Keyboard-leftArrowKey
        public Controls.KeyControl rightArrowKey => null;                             // SR:InputSystem.Keyboard-rightArrowKey
        public Controls.KeyControl upArrowKey => null;                                // SR:InputSystem.Keyboard-upArrowKey
        public Controls.KeyControl downArrowKey => null;                              // SR:InputSystem.Keyboard-downArrowKey
    }

    public class Pointer : InputDevice                                                // SR:InputSystem.Pointer
    {
        public Controls.DeltaControl delta { get; protected set; }                    // SR:InputSystem.Pointer-delta
        public static Pointer current { get; internal set; }                          // SR:InputSystem.Pointer-current
    }

    public class Mouse : Pointer                                                      // SR:InputSystem.Mouse
    {
        public Controls.ButtonControl rightButton { get; protected set; }             // SR:InputSystem.Mouse-rightButton
        public new static Mouse current { get; private set; }                         // SR:InputSystem.Mouse-current
    }
}

namespace UnityEngine.InputSystem.Controls
{
    public class AxisControl : InputControl<float> { }                                // SR:InputSystem.Controls.AxisControl
    public class ButtonControl : AxisControl                                          // SR:InputSystem.Controls.ButtonControl
    {
        public bool isPressed => false;                                               // SR:InputSystem.Controls.ButtonControl-isPressed
        public bool wasPressedThisFrame => false;                                     // SR:InputSystem.Controls.ButtonControl-wasPressedThisFrame
    }
    public class KeyControl : ButtonControl { }                                       // SR:InputSystem.Controls.KeyControl
    public class Vector2Control : InputControl<Vector2> { }                           // SR:InputSystem.Controls.Vector2Control
    public class DeltaControl : Vector2Control { }                                    // SR:InputSystem.Controls.DeltaControl
}
