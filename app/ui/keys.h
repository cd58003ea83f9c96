// Key codes for ImGui 1.86's io.KeysDown[], which its GLFW backend indexes by GLFW key code. The
// tests feed the same codes, so the shortcuts need no GLFW header.
#pragma once

namespace vplab::keys {

inline constexpr int kSpace = 32;
inline constexpr int kEscape = 256;
inline constexpr int kEnter = 257;
inline constexpr int kTab = 258;
inline constexpr int kBackspace = 259;
inline constexpr int kRight = 262;
inline constexpr int kLeft = 263;
inline constexpr int kPageUp = 266;
inline constexpr int kPageDown = 267;
inline constexpr int kHome = 268;
inline constexpr int kEnd = 269;
inline constexpr int kKeypadEnter = 335;
inline constexpr int kF1 = 290;
inline constexpr int kF11 = 300;
inline constexpr int kF12 = 301;
inline constexpr int kDigit1 = '1';  // '1'..'5' are consecutive
inline constexpr int kB = 'B';
inline constexpr int kC = 'C';
inline constexpr int kN = 'N';
inline constexpr int kO = 'O';
inline constexpr int kP = 'P';
inline constexpr int kQ = 'Q';
inline constexpr int kR = 'R';
inline constexpr int kS = 'S';
inline constexpr int kY = 'Y';
inline constexpr int kZ = 'Z';

}  // namespace vplab::keys
