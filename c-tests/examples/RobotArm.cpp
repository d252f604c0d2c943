// RobotArm.cpp: a SCARA robot the way an integrator drives it through the robot
// functions of the IMP-3 headers: its own kinematics registered with
// MCC_SetKinematicTrans, V6 moves in Cartesian space, a tool offset through the
// pre-process callback.
//
// The robot (group 0, channels 0..7; 500 pulses per degree or per mm):
//   joint 0  shoulder angle q1 (deg), link L1 = 200 mm
//   joint 1  elbow angle    q2 (deg), link L2 = 150 mm
//   joint 2  Z (mm), joint 3 the tool's rotation q4 (deg); joints 4..7 carry RX, RY, A,
//            B unchanged (a SCARA has none of its own).
// Cartesian (X, Y, Z, RX, RY, RZ, A, B) -> RZ = q1 + q2 + q4 (deg) in the W axis, and
//   X = L1 cos q1 + L2 cos(q1 + q2),  Y = L1 sin q1 + L2 sin(q1 + q2).
// Posture bit 0: 0 = right-handed elbow (q2 > 0), 1 = left-handed (q2 < 0).
//
// The link lengths live in the extension buffer the library allocates (zeroed) and hands
// to every kinematics call; the init callback fills it once.
//
// What it checks (all numbers from the formulas above):
//   1. after MCC_SetKinematicTrans the Cartesian position is fwd(joints 0) = (350, 0)
//   2. MCC_PtP_V6 to the ready pose inv(250, 100): MCC_GetCurPos reads (250, 100), the
//      pulses are the joints' (500 per degree)
//   3. MCC_Line_V6 to (250, -100, 50) turning RZ by 45: every Cartesian point the
//      kinematics got is on the line (within 1e-9 of its 206.16 mm), and RZ is 45 x the
//      fraction of the path covered (orientation interpolated linearly)
//   4. MCC_CircleXY_V6 about (200, -100): every point 50 mm from the centre
//   5. a target out of reach (L1 + L2 = 350) stops the group with 0xF106, the joints stay
//   6. with a tool offset of +10 mm in Y from the pre-process callback, MCC_Line_V6 to
//      (200, 0) ends at (200, 10)
//   7. a custom curve on the robot (MCC_CustomMotion): a circle of radius 20 mm about
//      (180, 10), given by arc length in the callbacks; every Cartesian point the
//      kinematics got lies on it (within 1e-9 of its 125.66 mm), and the tool ends where
//      it started, (200, 10)
#include "MotionSys.h"
#include <algorithm>
#include <mutex>
#include <vector>

namespace {

struct RobotParams
{
    double dfL1;
    double dfL2;
};

const double kDeg = 3.14159265358979323846 / 180.0;

// ---- The robot's kinematics (the integrator's own code) ----
bool Forward(const RobotParams &r, const double *j, double *c)
{
    double q1 = j[0] * kDeg, q12 = (j[0] + j[1]) * kDeg;
    c[0] = r.dfL1 * cos(q1) + r.dfL2 * cos(q12);
    c[1] = r.dfL1 * sin(q1) + r.dfL2 * sin(q12);
    c[2] = j[2];
    c[3] = j[4];
    c[4] = j[5];
    c[5] = j[0] + j[1] + j[3];
    c[6] = j[6];
    c[7] = j[7];
    return true;
}

bool Inverse(const RobotParams &r, const double *c, DWORD dwPosture, double *j)
{
    double x = c[0], y = c[1];
    double c2 = (x * x + y * y - r.dfL1 * r.dfL1 - r.dfL2 * r.dfL2) / (2 * r.dfL1 * r.dfL2);
    if (c2 < -1.0 || c2 > 1.0)
        return false; // out of reach
    double s2 = sqrt(1.0 - c2 * c2) * ((dwPosture & 1) ? -1.0 : 1.0);
    double q2 = atan2(s2, c2);
    double q1 = atan2(y, x) - atan2(r.dfL2 * s2, r.dfL1 + r.dfL2 * c2);
    j[0] = q1 / kDeg;
    j[1] = q2 / kDeg;
    j[2] = c[2];
    j[3] = c[5] - j[0] - j[1];
    j[4] = c[3];
    j[5] = c[4];
    j[6] = c[6];
    j[7] = c[7];
    return true;
}

// ---- What the library calls (on its engine thread, with no library lock held) ----
std::mutex g_mutex;
std::vector<std::vector<double> > g_points; // the Cartesian points inv was asked for
int g_nInits = 0;
int g_nUnreachable = 0;
double g_dfToolOffsetY = 0.0;

void MCC_CALLBACK InitRobot(void *pvExtension)
{
    RobotParams *r = static_cast<RobotParams *>(pvExtension);
    CHECK(r->dfL1 == 0.0 && r->dfL2 == 0.0); // zeroed by the library
    r->dfL1 = 200.0;
    r->dfL2 = 150.0;
    g_nInits++;
}

BOOL MCC_CALLBACK FwdKine(int, int nAxes, const double *pdfFrom, double *pdfTo, DWORD *pdwPosture, void *pvExt)
{
    (void)pdwPosture;
    CHECK_EQ(nAxes, 8);
    return Forward(*static_cast<RobotParams *>(pvExt), pdfFrom, pdfTo) ? 1 : 0;
}

BOOL MCC_CALLBACK InvKine(int, int, const double *pdfFrom, const double *, double *pdfTo, DWORD *pdwPosture, void *pvExt)
{
    bool ok = Inverse(*static_cast<RobotParams *>(pvExt), pdfFrom, *pdwPosture, pdfTo);
    std::lock_guard<std::mutex> lock(g_mutex);
    if (ok)
        g_points.push_back(std::vector<double>(pdfFrom, pdfFrom + 8));
    else
        g_nUnreachable++;
    return ok ? 1 : 0;
}

void MCC_CALLBACK ToolOffset(int, int, const double *, const double *, double *pdfOffset, void *)
{
    pdfOffset[1] = g_dfToolOffsetY;
}

// ---- A custom curve (the integrator's own geometry): a circle of radius kR whose
// centre lies kR in -X of where the curve starts, parameterised by arc length.
const double kR = 20.0;
int g_nCurveCleanups = 0;

double MCC_CALLBACK CurveStart(int, int, int, BOOL, const double *, void *)
{
    return 2.0 * 3.14159265358979323846 * kR; // total distance, mm
}

BOOL MCC_CALLBACK CurveInterp(int, int, int, const double *, const double *, double dfCurDist,
                              double, double *pdfNextPosOffset, void *)
{
    double th = dfCurDist / kR;
    pdfNextPosOffset[0] = kR * cos(th) - kR; // offsets from the start point
    pdfNextPosOffset[1] = kR * sin(th);
    return 1;
}

void MCC_CALLBACK CurveCleanup(int, int, void *)
{
    g_nCurveCleanups++;
}

std::vector<std::vector<double> > TakePoints()
{
    std::lock_guard<std::mutex> lock(g_mutex);
    std::vector<std::vector<double> > v;
    v.swap(g_points);
    return v;
}

// A kinematic group's pulse position is its joints', round(joint x pulses per UU) (the
// library's rule for joints, docs/compatibility.md "Robot kinematics"; other axes count
// whole pulses toward 0, PulsesOf).
void CheckPulsesAreJoints(const double j[8])
{
    long p[8];
    CHECK_EQ(MCC_GetPulsePos(&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], 0), NO_ERR);
    for (int i = 0; i < 8; i++)
        CHECK_EQ(p[i], lround(j[i] * EX_PPR));
}

} // namespace

int main()
{
    if (InitSys8() != NO_ERR)
        return check_done("RobotArm");
    const WORD g = (WORD)g_nGroupIndex;
    printf("RobotArm: a SCARA robot with its own kinematics on group %d\n", g);
    RobotParams robot = {200.0, 150.0};

    // 1. The group becomes a robot.
    CHECK_EQ(MCC_SetKinematicTrans(FwdKine, InvKine, sizeof(RobotParams), InitRobot, g), NO_ERR);
    CHECK_EQ(g_nInits, 1);
    PrintPos(g, "Stretched out (all joints 0)");
    CheckPosXYZ(g, 350, 0, 0);

    // 2. Joint move to the ready pose.
    const double ready[8] = {250, 100, 50, 0, 0, 0, 0, 0};
    double jReady[8];
    CHECK(Inverse(robot, ready, 0, jReady));
    MCC_SetPtPSpeed(100, g); // 50 deg/s
    CHECK(MCC_PtP_V6(jReady[0], jReady[1], jReady[2], jReady[3], jReady[4], jReady[5], jReady[6], jReady[7], g) >= 0);
    WaitStop(g);
    PrintPos(g, "Ready (MCC_PtP_V6)");
    CheckPos8(g, ready);
    CheckPulsesAreJoints(jReady);
    TakePoints();

    // 3. A straight line, the tool turning 45 degrees on the way.
    MCC_SetFeedSpeed(50, g);
    CHECK(MCC_Line_V6(250, -100, 50, 0, 0, 45, 0, 0, 0, g) >= 0);
    WaitStop(g);
    PrintPos(g, "After MCC_Line_V6");
    std::vector<std::vector<double> > pts = TakePoints();
    CHECK(pts.size() > 100);
    double dfWorst = 0;
    for (size_t k = 0; k < pts.size(); k++)
    {
        const std::vector<double> &c = pts[k];
        double dfOff = fabs(c[0] - 250.0); // the line is x = 250
        if (dfOff > dfWorst)
            dfWorst = dfOff;
        double dfFraction = (100.0 - c[1]) / 200.0;
        CHECK_NEAR(c[5], 45.0 * dfFraction, 1e-9);
        CHECK_NEAR(c[2], 50.0, 1e-12);
    }
    printf("  %zu points, farthest %.3g mm off the line\n", pts.size(), dfWorst);
    CHECK(dfWorst <= 1e-9 * 200.0);
    const double lineEnd[8] = {250, -100, 50, 0, 0, 45, 0, 0};
    double jEnd[8];
    CHECK(Inverse(robot, lineEnd, 0, jEnd));
    CheckPos8(g, lineEnd);
    CheckPulsesAreJoints(jEnd);

    // 4. A circle about (200, -100), the tool turning back to 0 over the turn.
    CHECK(MCC_CircleXY_V6(200, -100, 0, 0, 0, CIR_CCW, 0, g) >= 0);
    WaitStop(g);
    pts = TakePoints();
    for (size_t k = 0; k < pts.size(); k++)
        CHECK_NEAR(hypot(pts[k][0] - 200.0, pts[k][1] + 100.0), 50.0, 1e-9 * 314.2);
    PrintPos(g, "After MCC_CircleXY_V6");
    CheckPosXYZ(g, 250, -100, 50);

    // 5. Out of reach: the group stops with 0xF106 where the arm still reached.
    long before[8], after[8];
    CHECK(MCC_Line_V6(400, -100, 50, 0, 0, 0, 0, 0, 0, g) >= 0);
    WaitStop(g);
    printf("MCC_Line_V6 to (400, -100): error record 0x%X (inverse kinematics)\n", MCC_GetErrorCode(g));
    CHECK_EQ(MCC_GetErrorCode(g), 0xF106);
    CHECK(g_nUnreachable == 1);
    CHECK_EQ(MCC_GetPulsePos(&before[0], &before[1], &before[2], &before[3], &before[4], &before[5], &before[6], &before[7], g), NO_ERR);
    MCC_TimeDelay(20);
    CHECK_EQ(MCC_GetPulsePos(&after[0], &after[1], &after[2], &after[3], &after[4], &after[5], &after[6], &after[7], g), NO_ERR);
    for (int i = 0; i < 8; i++)
        CHECK_EQ(before[i], after[i]);
    double p[8];
    GetPos(g, p);
    printf("  stopped at X = %.3f (reach: sqrt(350^2 - 100^2) = %.3f)\n", p[0], sqrt(350.0 * 350 - 100 * 100));
    CHECK(p[0] <= sqrt(350.0 * 350 - 100 * 100) + 1e-9);
    CHECK_EQ(MCC_ClearError(g), NO_ERR);

    // 6. A tool offset through the pre-process callback.
    g_dfToolOffsetY = 10.0;
    CHECK_EQ(MCC_SetPreProcessMotionCommandCallback(ToolOffset, g), NO_ERR);
    CHECK(MCC_Line_V6(200, 0, 50, 0, 0, 0, 0, 0, 0, g) >= 0);
    WaitStop(g);
    PrintPos(g, "After MCC_Line_V6 to (200, 0) with a +10 mm Y tool offset");
    CheckPosXYZ(g, 200, 10, 50);

    // 7. A custom curve on the robot: the library's own speed profile over the distance
    //    CurveStart returns, the geometry from CurveInterp, the joints from InvKine.
    g_dfToolOffsetY = 0.0;
    TakePoints();
    CHECK(MCC_CustomMotion(CurveStart, CurveInterp, CurveCleanup, NULL, g) >= 0);
    WaitStop(g);
    PrintPos(g, "After MCC_CustomMotion (a 20 mm circle about (180, 10))");
    pts = TakePoints();
    CHECK(pts.size() > 100);
    dfWorst = 0.0;
    for (size_t k = 0; k < pts.size(); k++)
        dfWorst = std::max(dfWorst, fabs(hypot(pts[k][0] - 180.0, pts[k][1] - 10.0) - kR));
    printf("custom curve: %zu points, worst distance from the circle %.3g mm\n", pts.size(), dfWorst);
    CHECK(dfWorst <= 1e-9 * 2.0 * 3.14159265358979323846 * kR);
    CHECK_EQ(g_nCurveCleanups, 1);
    CheckPosXYZ(g, 200, 10, 50);

    Close();
    return check_done("RobotArm");
}
