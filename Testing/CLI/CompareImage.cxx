// silhouette_compare_image IMAGE.png BASELINE.png THRESHOLD TEMP_DIR
// Compares a PNG the program wrote with its baseline the way VTK's own
// regression tests compare render windows (vtkTesting, vtkImageDifference,
// error against THRESHOLD; VTK's default is 0.15). On failure the test
// image and the difference image are left in TEMP_DIR. Exit 0 when they match.
#include <vtkNew.h>
#include <vtkTesting.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 5)
  {
    std::cerr << "usage: " << argv[0] << " IMAGE.png BASELINE.png THRESHOLD TEMP_DIR\n";
    return 2;
  }
  const std::string image = argv[1];
  const double threshold = std::atof(argv[3]);
  vtkNew<vtkTesting> testing;
  testing->AddArgument("-V");
  // vtkTesting puts a relative baseline under its data root.
  const std::string baseline = std::filesystem::absolute(argv[2]).string();
  testing->AddArgument(baseline.c_str());
  testing->AddArgument("-T");
  testing->AddArgument(argv[4]);
  const int result = testing->RegressionTest(image, threshold, std::cout);
  std::cout << image << ": difference " << testing->GetImageDifference() << " (threshold "
            << threshold << ") " << (result == vtkTesting::PASSED ? "passed" : "FAILED")
            << std::endl;
  return result == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
