// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the Python module of the VTP_geodesics package.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_GEODESICS_PYTHON_INTERRUPT_H
#define VTP_GEODESICS_PYTHON_INTERRUPT_H

// Ctrl-C (and progress) during the long calls that run rows on the solver's threads: matrices.cpp (distance
// matrices) and patches.cpp (polar patches). The sink of the library's compute_each() or
// compute_each_polar_patch() calls Interrupt_check::row_done() after each row; on the thread that called into
// the module, every 0.2 s, it takes the GIL, checks for a pending signal and throws Python_error_pending, which
// stops the handing out of rows; the caller then raises the saved Python exception (KeyboardInterrupt).

#include "core_solver.h"

#include <chrono>
#include <sstream>
#include <string>
#include <thread>

namespace vtp_python {

// Set in the sink by the thread that called into the module when Python reports a pending exception
// (KeyboardInterrupt): thrown through compute_each() or compute_each_polar_patch(),
// which stop handing out rows.
struct Python_error_pending
{};

// The error indicator fetched while the GIL was held briefly inside a computation, restored afterwards.
struct Saved_python_error
{
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
  void fetch() { PyErr_Fetch(&type, &value, &traceback); }
  [[noreturn]] void restore_and_throw()
  {
    PyErr_Restore(type, value, traceback);
    type = value = traceback = nullptr;
    throw py::error_already_set();
  }
};

// Calls Python every 0.2 s from the thread that entered the module (only that thread may run signal handlers):
// checks for a pending signal (Ctrl-C) and, if asked, writes the progress to sys.stderr.
class Interrupt_check
{
public:
  Interrupt_check(std::size_t total, bool progress)
    : m_caller(std::this_thread::get_id()), m_last(std::chrono::steady_clock::now()), m_total(total),
      m_progress(progress)
  {}

  // Called (serially) after each row; throws Python_error_pending once Python has an exception to raise.
  void row_done()
  {
    const std::size_t done = ++m_done;
    if(std::this_thread::get_id() != m_caller)
      return;
    const auto now = std::chrono::steady_clock::now();
    if(now - m_last < std::chrono::milliseconds(200) && done != m_total)
      return;
    m_last = now;
    py::gil_scoped_acquire gil;
    if(m_progress)
      write_progress(done);
    if(PyErr_CheckSignals() != 0)
    {
      error.fetch();
      throw Python_error_pending();
    }
  }

  void finish()
  {
    if(m_progress)
    {
      write_progress(m_done);
      write("\n");
    }
  }

  Saved_python_error error;

private:
  void write_progress(std::size_t done)
  {
    std::ostringstream s;
    s << "\rvtp_geodesics: " << done << " / " << m_total << " rows";
    write(s.str());
  }

  static void write(const std::string& text)
  {
    try
    {
      py::module_::import("sys").attr("stderr").attr("write")(text);
    }
    catch(py::error_already_set&)
    {
    }
  }

  std::thread::id m_caller;
  std::chrono::steady_clock::time_point m_last;
  std::size_t m_total, m_done = 0;
  bool m_progress;
};

} // namespace vtp_python

#endif // VTP_GEODESICS_PYTHON_INTERRUPT_H
