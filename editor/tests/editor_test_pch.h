// Precompiled once for every editor suite (the first suite builds it, the others reuse
// it: CMake's REUSE_FROM): the editor library's Qt headers and QtTest. <QtTest> alone
// took about 8 s of CPU to parse in each suite.
#pragma once

#include "editor_pch.h"

#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
