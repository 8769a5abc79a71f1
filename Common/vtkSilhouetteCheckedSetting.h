/**
 * Header-only and private: the setter the project's VTK classes use for
 * settings with a valid range. Shared by modules that otherwise have nothing
 * in common (the analytic sources need VTK alone), so it lives below them all.
 *
 * Rule: a value outside [lo, hi] is clamped with a warning naming the setting;
 * NaN is refused with a warning and the setting stays. Modified() is called only
 * when the stored value changes.
 */
#ifndef vtkSilhouetteCheckedSetting_h
#define vtkSilhouetteCheckedSetting_h

#include "vtkObject.h"
#include "vtkSetGet.h"

namespace vtkSilhouetteCheckedSetting
{

/// Stores `value` in `setting` under the rule above; returns whether the
/// setting changed.
template<typename T>
bool Store(vtkObject* self, const char* name, T& setting, T value, T lo, T hi)
{
  if (value != value) // NaN
  {
    vtkWarningWithObjectMacro(
      self, "Set" << name << ": NaN is not a value; " << name << " stays " << setting << ".");
    return false;
  }
  const T clamped = value < lo ? lo : (value > hi ? hi : value);
  if (clamped != value)
  {
    vtkWarningWithObjectMacro(self,
      "Set" << name << "(" << value << ") is outside [" << lo << ", " << hi << "]; using "
            << clamped << ".");
  }
  if (clamped == setting)
  {
    return false;
  }
  setting = clamped;
  return true;
}

} // namespace vtkSilhouetteCheckedSetting

/// Defines Class::SetName(Type) under the rule above. Used as a statement,
/// with a `;`.
#define vtkSilhouetteCheckedSetterMacro(Class, Name, Type, Lo, Hi)                                 \
  void Class::Set##Name(Type value)                                                                \
  {                                                                                                \
    if (vtkSilhouetteCheckedSetting::Store<Type>(this, #Name, this->Name, value, Lo, Hi))          \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  static_assert(true, "")

#endif
// VTK-HeaderTest-Exclude: vtkSilhouetteCheckedSetting.h
