// Mono test harness for the C# binding (csharp/MCCL.cs) against libMCCLPCI_IMP.so.
//
// Build and run (csharp/tests/run.sh does this; CTest runs it as `csharp_mono`):
//   mcs -langversion:7.2 -warnaserror+ -out:mccl_mono.exe csharp/MCCL.cs csharp/tests/*.cs
//   MCCL_CLOCK=fast LD_LIBRARY_PATH=<dir of libMCCLPCI_IMP.so> mono mccl_mono.exe [name-filter]
// [DllImport("MCCLPCI_IMP.dll")] is resolved by Mono to libMCCLPCI_IMP.so on LD_LIBRARY_PATH
// (the installed aliases libMCCLPCI_IMP.dll.so / MCCLPCI_IMP.dll.so work the same way).
//
// Adding tests: write a static void method in any file of this directory and mark it
// [MonoTest(order)]; tests run in (order, name) order, each after the previous one has closed
// the system. Planned, once the library exports them: a GeneralMotion sequence (order 300,
// MCC_Line/MCC_GetCurPos through Fixture.InitOneCard) and an encoder-compare callback that
// aborts motion from the engine thread (order 400; keep the ENCISR delegate in a static field
// and never let an exception escape it: both are fatal on the engine thread).
using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

/// <summary>Marks a test method; lower orders run first.</summary>
[AttributeUsage(AttributeTargets.Method)]
public sealed class MonoTestAttribute : Attribute
{
    public readonly int Order;
    public MonoTestAttribute(int order) { Order = order; }
}

/// <summary>Assertions: a failure is counted and printed, the test goes on.</summary>
public static class Check
{
    public static int Checks;
    public static int Failures;

    public static void Eq<T>(T actual, T expected, string what)
    {
        Checks++;
        if (!EqualityComparer<T>.Default.Equals(actual, expected))
        {
            Failures++;
            Console.WriteLine("  FAIL {0}: got {1}, expected {2}", what, actual, expected);
        }
    }

    public static void True(bool cond, string what)
    {
        Checks++;
        if (!cond)
        {
            Failures++;
            Console.WriteLine("  FAIL {0}", what);
        }
    }
}

/// <summary>Shared setup for tests that need a running system.</summary>
public static class Fixture
{
    public const ushort CARD = 0;

    /// <summary>Mechanism parameters the examples manual uses (pulse output, no limits).</summary>
    public static SYS_MAC_PARAM MacParam()
    {
        var p = new SYS_MAC_PARAM();
        p.wPosToEncoderDir = 0;
        p.wRPM = 3000;
        p.dwPPR = 500;
        p.dfPitch = 1.0;
        p.dfGearRatio = 1.0;
        p.dfHighLimit = 50000.0;
        p.dfLowLimit = -50000.0;
        p.dfHighLimitOffset = 0;
        p.dfLowLimitOffset = 0;
        p.wPulseMode = MCCL.DDA_FMT_PD;
        p.wPulseWidth = 100;
        p.wCommandMode = MCCL.OCM_PULSE;
        p.wOverTravelUpSensorMode = MCCL.SL_UNUSED;
        p.wOverTravelDownSensorMode = MCCL.SL_UNUSED;
        return p;
    }

    /// <summary>One IMP-III card, every channel configured, group 0 = X,Y,Z on channels 0..2.
    /// Returns the MCC_InitSystem result.</summary>
    public static int InitOneCard()
    {
        var p = MacParam();
        for (ushort ch = 0; ch < MCCL.MAX_AXIS_NUM; ch++)
            Check.Eq(MCCL.MCC_SetMacParam(ref p, ch, CARD), MCCL.NO_ERR, "SetMacParam ch " + ch);
        Check.Eq(MCCL.MCC_CloseAllGroups(), MCCL.NO_ERR, "CloseAllGroups");
        Check.Eq(MCCL.MCC_CreateGroup(0, 1, 2, -1, -1, -1, -1, -1, CARD), 0, "CreateGroup");
        var cards = new SYS_CARD_CONFIG[MCCL.MAX_CARD_NUM];
        cards[CARD].wCardType = MCCL.IMP_III_8_AXIS_PCI_CARD;
        return MCCL.MCC_InitSystem(2, cards, 1);
    }
}

public static class Program
{
    public static int Main(string[] args)
    {
        var tests = Assembly.GetExecutingAssembly().GetTypes()
            .SelectMany(t => t.GetMethods(BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic))
            .Select(m => new { Method = m, Attr = m.GetCustomAttribute<MonoTestAttribute>() })
            .Where(x => x.Attr != null)
            .Where(x => args.Length == 0 || args.Any(a => x.Method.Name.Contains(a)))
            .OrderBy(x => x.Attr.Order).ThenBy(x => x.Method.Name)
            .ToList();
        Console.WriteLine("mono {0}, IntPtr.Size {1}, MCCL_CLOCK={2}",
            Type.GetType("Mono.Runtime") != null ? "runtime" : "(not mono)", IntPtr.Size,
            Environment.GetEnvironmentVariable("MCCL_CLOCK") ?? "(unset)");
        int failedTests = 0;
        foreach (var t in tests)
        {
            int before = Check.Failures;
            string error = null;
            try { t.Method.Invoke(null, null); }
            catch (TargetInvocationException e) { error = e.InnerException.ToString(); }
            finally { MCCL.MCC_CloseSystem(); }
            if (error != null) { Check.Failures++; Console.WriteLine("  EXCEPTION " + error); }
            bool ok = Check.Failures == before;
            if (!ok) failedTests++;
            Console.WriteLine("{0} {1}", ok ? "ok  " : "FAIL", t.Method.Name);
        }
        Console.WriteLine("{0} tests, {1} checks, {2} failed checks, {3} failed tests",
            tests.Count, Check.Checks, Check.Failures, failedTests);
        if (tests.Count == 0) { Console.WriteLine("FAIL: no tests matched"); return 1; }
        return Check.Failures == 0 ? 0 : 1;
    }
}
