// Struct layouts as the .NET marshaller sees them, against the C sizes of the vendor
// (Windows) layout, which libMCCLPCI_IMP keeps on Linux (docs/vendor-interface.md,
// "Struct layouts").
using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;

public static class LayoutTests
{
    // Written from docs/vendor-interface.md, not from the generator.
    static readonly Dictionary<Type, int> Sizes = new Dictionary<Type, int>
    {
        { typeof(SYS_MAC_PARAM), 72 },
        { typeof(SYS_MAC_PARAM_EX), 72 },
        { typeof(SYS_ENCODER_CONFIG), 16 },
        { typeof(ENCODER_CONFIG), 16 },
        { typeof(SYS_PULSE_CONFIG), 8 },
        { typeof(PULSE_CONFIG), 8 },
        { typeof(SYS_HOME_CONFIG), 56 },
        { typeof(SYS_HOME_CONFIG_EX), 88 },
        { typeof(SYS_COMP_PARAM), 2056 },
        { typeof(SYS_CARD_CONFIG), 8 },
        { typeof(HOME_CONFIG), 16 },
        { typeof(SYS_MACH_PARAM), 104 },
        { typeof(SYS_GROUP_INFO), 36 },
        { typeof(SYS_GROUP_CONFIG), 3840 },
        { typeof(COMMAND_INFO), 104 },
        { typeof(LIOINT), 24 },
        { typeof(ENCINT), 16 },
        { typeof(PCLINT), 16 },
        { typeof(ADCINT), 10 },
        { typeof(RIOINT), 8 },
        { typeof(TMRINT), 1 },
        { typeof(HSKINT), 1 },
    };

    [MonoTest(100)]
    static void StructSizes()
    {
        foreach (var kv in Sizes)
            Check.Eq(Marshal.SizeOf(kv.Key), kv.Value, "Marshal.SizeOf(" + kv.Key.Name + ")");
        // Every struct of the binding has an expected size here (new ones must be added).
        var bindingStructs = typeof(SYS_MAC_PARAM).Assembly.GetTypes()
            .Where(t => t.IsValueType && !t.IsEnum && t.IsPublic && t.Namespace == null
                        && t.IsLayoutSequential);
        foreach (var t in bindingStructs)
            Check.True(Sizes.ContainsKey(t), "no expected size for struct " + t.Name);
    }

    static void Off<T>(string field, int offset)
    {
        Check.Eq((int)Marshal.OffsetOf(typeof(T), field), offset, typeof(T).Name + "." + field);
    }

    [MonoTest(101)]
    static void FieldOffsets()
    {
        Off<SYS_MAC_PARAM>("dwPPR", 4); Off<SYS_MAC_PARAM>("dfPitch", 8);
        Off<SYS_MAC_PARAM>("dfLowLimitOffset", 48); Off<SYS_MAC_PARAM>("wPulseMode", 56);
        Off<SYS_MAC_PARAM>("wOverTravelDownSensorMode", 66);
        Off<SYS_MAC_PARAM_EX>("dwRPM", 8); Off<SYS_MAC_PARAM_EX>("dfPitch", 16);
        Off<SYS_ENCODER_CONFIG>("wPaddle", 12);
        Off<SYS_HOME_CONFIG>("nIndexCount", 8); Off<SYS_HOME_CONFIG>("dfAccTime", 16);
        Off<SYS_HOME_CONFIG>("dfOffset", 48);
        Off<SYS_HOME_CONFIG_EX>("dfStableTime", 56); Off<SYS_HOME_CONFIG_EX>("wTolerance", 82);
        Off<SYS_COMP_PARAM>("nForwardTable", 8); Off<SYS_COMP_PARAM>("nBackwardTable", 1032);
        Off<HOME_CONFIG>("dfOffset", 8);
        Off<SYS_MACH_PARAM>("stHome", 64); Off<SYS_MACH_PARAM>("stEncoder", 80);
        Off<SYS_MACH_PARAM>("wOverTravelUpSensorMode", 96);
        Off<SYS_GROUP_CONFIG>("stGroupInfo", 384);
        Off<COMMAND_INFO>("dfFeedSpeed", 8); Off<COMMAND_INFO>("dfPos", 16);
        Off<COMMAND_INFO>("dfAcctime", 80); Off<COMMAND_INFO>("nMotionPhase", 96);
        Off<COMMAND_INFO>("nCommandIndex_LD", 100);
        Off<LIOINT>("HOME7", 23); Off<ADCINT>("TAG", 9);
    }

    static void Isr(ref ENCINT v) { v.COMP0 = 1; }

    [MonoTest(102)]
    static void DelegatesMarshal()
    {
        // Every callback type can be turned into a native function pointer.
        MCCL.ENCISR enc = Isr;
        Check.True(Marshal.GetFunctionPointerForDelegate(enc) != IntPtr.Zero, "ENCISR pointer");
        MCCL.CYCLE_INTERRUPT_ISR cyc = () => { };
        Check.True(Marshal.GetFunctionPointerForDelegate(cyc) != IntPtr.Zero, "CYCLE_INTERRUPT_ISR pointer");
        GC.KeepAlive(enc);
        GC.KeepAlive(cyc);
    }
}
