#include <particulate/core/parameter_text.h>
#include <particulate/deformation/deformation_parameters.h>

#include <deal.II/base/utilities.h>

namespace particulate {
  namespace deformation {
    using namespace dealii;

    namespace {
      std::string
      name_of(const DeformationParameters::Method method)
      {
        using Method = DeformationParameters::Method;
        switch (method)
          {
            case Method::laplace_kappa:
              return "laplace-kappa";
            case Method::laplace_alpha:
              return "laplace-alpha";
            case Method::pde_basic:
              return "pde-basic";
            case Method::pde_robust:
              return "pde-robust";
            case Method::none:
              break;
          }
        return "none";
      }

      std::string
      name_of(const DeformationParameters::Following following)
      {
        using Following = DeformationParameters::Following;
        switch (following)
          {
            case Following::carry_surface:
              return "carry surface vertices";
            case Following::carry_neighbourhood:
              return "carry neighbourhood";
            case Following::readapt:
              break;
          }
        return "re-adapt";
      }
    } // namespace



    void
    DeformationParameters::declare(ParameterHandler &prm)
    {
      const DeformationParameters defaults;
      const auto number = [](const double v) { return core::number_text(v); };
      prm.enter_subsection("Mesh deformation");
      prm.declare_entry(
        "Method",
        name_of(defaults.method),
        Patterns::Selection(
          "none|laplace-kappa|laplace-alpha|pde-basic|pde-robust"),
        "r-adaptivity (thesis §5.5-5.7): laplace-kappa pulls vertices towards "
        "the bodies by weighted Laplacian smoothing, level by level; "
        "laplace-alpha also puts vertices onto the surfaces; pde-basic and "
        "pde-robust solve Grajewski's deformation problem (one step, or as "
        "many blended steps as the monitor needs).");
      prm.declare_entry("Width",
                        number(defaults.width),
                        Patterns::Double(0.),
                        "[m] Distance from the body surfaces within which the "
                        "mesh is refined: the reach of the smoothing weight, "
                        "and the ramp of the PDE monitor f = min{1, max{|d| / "
                        "Width, Smallest cell ratio}}.");
      prm.declare_entry(
        "Peak weight",
        number(defaults.peak_weight),
        Patterns::Double(1.),
        "Laplace-kappa/alpha: smoothing weight of a vertex on a "
        "surface (1 at distance Width and beyond).");
      prm.declare_entry("Relaxation",
                        number(defaults.relaxation),
                        Patterns::Double(0., 1.),
                        "omega of the weighted smoother, eq. 5.27.");
      prm.declare_entry("Sweeps per level",
                        core::list_text(defaults.sweeps_per_level),
                        Patterns::List(Patterns::Integer(0), 1),
                        "Smoothing sweeps on each level, coarsest first; the "
                        "last entry repeats for the finer levels.");
      prm.declare_entry("Smallest cell ratio",
                        number(defaults.smallest_cell_ratio),
                        Patterns::Double(0., 1.),
                        "PDE methods: epsilon, the smallest over the largest "
                        "target cell size.");
      prm.declare_entry("ODE steps",
                        std::to_string(defaults.ode_steps),
                        Patterns::Integer(1),
                        "PDE methods: Runge-Kutta steps of the vertex paths "
                        "(eq. 5.22).");
      prm.declare_entry("Robust step ratio",
                        number(defaults.step_ratio),
                        Patterns::Double(1.01),
                        "pde-robust: the target cell size changes by at most "
                        "this factor per adaptation step.");
      prm.declare_entry("Projection range",
                        number(defaults.projection_range),
                        Patterns::Double(0., 0.5),
                        "laplace-alpha: vertices (on every level) closer to a "
                        "surface than this fraction of their shortest edge "
                        "are put onto it.");
      prm.declare_entry("Minimum cell quality",
                        number(defaults.min_quality),
                        Patterns::Double(0., 1.),
                        "No move may leave a cell with a scaled Jacobian below "
                        "this (or below its value before the move): such moves "
                        "are cut back.");
      prm.declare_entry(
        "Moving bodies",
        name_of(defaults.following),
        Patterns::Selection(
          "re-adapt|carry surface vertices|carry neighbourhood"),
        "How the mesh follows bodies that move: re-adapt adapts the "
        "undeformed mesh afresh every time step; 'carry surface vertices' "
        "(laplace-alpha only) moves the vertices on a surface with their "
        "body and smooths the others (thesis §5.7), so that no vertex "
        "crosses a surface; 'carry neighbourhood' (any Method, also none) "
        "moves every vertex within 'Carried zone width' of a body's surface "
        "rigidly with the body's translation, and those up to 'Carried zone "
        "fade' farther out by a share that falls smoothly to zero, so that "
        "no velocity node enters or leaves a body while the mesh is carried "
        "(the mesh velocity enters the flow as ALE; rotations are not "
        "followed, which spheres and disks do not need). Both carrying "
        "modes adapt afresh, and carry the flow over by interpolation, only "
        "when the quality falls below 'Re-adaptation quality' or above "
        "'Re-adaptation aspect ratio' (or a surface vertex cannot follow).");
      prm.declare_entry(
        "Carried zone width",
        number(defaults.carried_zone_width),
        Patterns::Double(0.),
        "[m] 'carry neighbourhood': vertices closer than this to a body's "
        "surface (and those inside it) move rigidly with the body. At least "
        "a cell beyond the surface, so that the cut cells keep their shape.");
      prm.declare_entry(
        "Carried zone fade",
        number(defaults.carried_zone_fade),
        Patterns::Double(0.),
        "[m] 'carry neighbourhood': beyond 'Carried zone width' the "
        "vertices move by a share of the body's displacement that falls "
        "smoothly from 1 to 0 over this distance. Longer fades shear and "
        "compress the cells less, so the mesh is carried farther before it "
        "is adapted afresh.");
      prm.declare_entry(
        "Re-adaptation quality",
        number(defaults.readaptation_quality),
        Patterns::Double(0., 1.),
        "'carry surface vertices' and 'carry neighbourhood': adapt afresh "
        "when the smallest scaled "
        "Jacobian of the carried mesh falls below this (and below that of "
        "the last fresh adaptation). Above 'Minimum cell quality', which "
        "no move may cross.");
      prm.declare_entry(
        "Re-adaptation aspect ratio",
        number(defaults.readaptation_aspect_ratio),
        Patterns::Double(1.),
        "Both carrying modes: adapt afresh when the largest aspect "
        "ratio of the carried mesh exceeds this (and that of the last fresh "
        "adaptation): carried vertices stretch the cells between them and "
        "their undeformed neighbours.");
      prm.leave_subsection();
    }



    void
    DeformationParameters::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Mesh deformation");
      const std::string m = prm.get("Method");
      method              = m == "laplace-kappa" ? Method::laplace_kappa :
                            m == "laplace-alpha" ? Method::laplace_alpha :
                            m == "pde-basic"     ? Method::pde_basic :
                            m == "pde-robust"    ? Method::pde_robust :
                                                   Method::none;
      width               = prm.get_double("Width");
      peak_weight         = prm.get_double("Peak weight");
      relaxation          = prm.get_double("Relaxation");
      sweeps_per_level.clear();
      for (const int s : Utilities::string_to_int(
             Utilities::split_string_list(prm.get("Sweeps per level"))))
        sweeps_per_level.push_back(s);
      smallest_cell_ratio       = prm.get_double("Smallest cell ratio");
      ode_steps                 = prm.get_integer("ODE steps");
      step_ratio                = prm.get_double("Robust step ratio");
      projection_range          = prm.get_double("Projection range");
      min_quality               = prm.get_double("Minimum cell quality");
      const std::string moving  = prm.get("Moving bodies");
      following                 = moving == "re-adapt" ? Following::readapt :
                                  moving == "carry surface vertices" ?
                                                         Following::carry_surface :
                                                         Following::carry_neighbourhood;
      readaptation_quality      = prm.get_double("Re-adaptation quality");
      readaptation_aspect_ratio = prm.get_double("Re-adaptation aspect ratio");
      carried_zone_width        = prm.get_double("Carried zone width");
      carried_zone_fade         = prm.get_double("Carried zone fade");
      prm.leave_subsection();
    }
  } // namespace deformation
} // namespace particulate
