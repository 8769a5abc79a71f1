// Makes vtkRenderWindow::New() return a vtkOSMesaRenderWindow (and
// vtkRenderWindowInteractor::New() a vtkGenericRenderWindowInteractor) in
// every program that loads this library, so existing code renders through
// OSMesa unchanged.
//
// vtkObjectFactory::CreateInstance asks the registered factories in the
// order they were registered and takes the first answer. This factory is
// registered when the library is loaded, before the program's own static
// initialisers run (those register VTK's OpenGL2 and UI factories through
// vtkModuleAutoInit, for C++ programs; Python's vtkmodules register them at
// import). A VTK library loaded earlier may already have registered them,
// though: the overrides of vtkRenderWindow and vtkRenderWindowInteractor of
// the factories registered before this one are switched off.
#include "vtkOSMesaRenderWindow.h"

#include <vtkCollection.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkObjectFactory.h>
#include <vtkObjectFactoryCollection.h>
#include <vtkOverrideInformation.h>
#include <vtkOverrideInformationCollection.h>
#include <vtkVersionMacros.h>

#include <string>

namespace
{

vtkObject* NewOSMesaRenderWindow()
{
  return vtkOSMesaRenderWindow::New();
}

vtkObject* NewGenericInteractor()
{
  return vtkGenericRenderWindowInteractor::New();
}

class vtkOSMesaObjectFactory : public vtkObjectFactory
{
public:
  static vtkOSMesaObjectFactory* New()
  {
    auto* factory = new vtkOSMesaObjectFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  vtkTypeMacro(vtkOSMesaObjectFactory, vtkObjectFactory);

  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override
  {
    return "silhouette_osmesa: OSMesa offscreen render windows without X";
  }

protected:
  vtkOSMesaObjectFactory()
  {
    this->RegisterOverride("vtkRenderWindow", "vtkOSMesaRenderWindow",
      "OSMesa offscreen render window", 1, NewOSMesaRenderWindow);
    // X's interactor would open a display; the generic one has no event loop
    // of its own, which suits an offscreen window (event playback works).
    this->RegisterOverride("vtkRenderWindowInteractor", "vtkGenericRenderWindowInteractor",
      "interactor without a windowing system", 1, NewGenericInteractor);
  }
};

// Switches off `className`'s overrides in the factories registered before `ours`.
void DisableEarlierOverrides(vtkObjectFactory* ours, const char* className)
{
  vtkObjectFactoryCollection* factories = vtkObjectFactory::GetRegisteredFactories();
  vtkCollectionSimpleIterator iterator;
  factories->InitTraversal(iterator);
  while (vtkObjectFactory* factory = factories->GetNextObjectFactory(iterator))
  {
    if (factory == ours)
    {
      return;
    }
    for (int i = 0; i < factory->GetNumberOfOverrides(); ++i)
    {
      if (std::string(factory->GetClassOverrideName(i)) == className)
      {
        factory->SetEnableFlag(0, className, factory->GetClassOverrideWithName(i));
      }
    }
  }
}

__attribute__((constructor)) void RegisterOSMesaFactory()
{
  vtkOSMesaObjectFactory* factory = vtkOSMesaObjectFactory::New();
  vtkObjectFactory::RegisterFactory(factory);
  DisableEarlierOverrides(factory, "vtkRenderWindow");
  DisableEarlierOverrides(factory, "vtkRenderWindowInteractor");
  factory->Delete(); // the registry holds it from now on, and frees it at exit
}

} // namespace
