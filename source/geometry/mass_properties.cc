#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>

#include <Eigen/Eigenvalues>

#include <sstream>

namespace particulate {
  namespace geometry {

    MassProperties
    MassProperties::transformed(const Pose &pose) const
    {
      MassProperties out;
      out.volume  = volume;
      out.centre  = pose.to_world(centre);
      out.inertia = pose.rotation() * inertia * pose.rotation().transpose();
      return out;
    }

    Eigen::Matrix3d
    MassProperties::inertia_about(const Eigen::Vector3d &p) const
    {
      const Eigen::Vector3d d = centre - p;
      return inertia
             + volume
                 * (d.squaredNorm() * Eigen::Matrix3d::Identity()
                    - d * d.transpose());
    }

    Pose
    MassProperties::principal_frame(Eigen::Vector3d *moments) const
    {
      // Eigen sorts the eigenvalues of a self-adjoint matrix increasingly.
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
      Eigen::Matrix3d axes = eig.eigenvectors();
      if (axes.determinant() < 0.)
        axes.col(2) *= -1.;
      if (moments)
        *moments = eig.eigenvalues();
      return Pose(axes, centre);
    }

    MassProperties
    compute_mass_properties(const TriangleMesh &mesh)
    {
      if (mesh.triangles.empty())
        throw GeometryError(
          "compute_mass_properties: the mesh has no triangles.");

      // Reference point: the vertex mean, so that the tetrahedra are small
      // relative to their coordinates (less cancellation than the origin).
      Eigen::Vector3d o = Eigen::Vector3d::Zero();
      for (const auto &v : mesh.vertices)
        o += v;
      o /= static_cast<double>(mesh.vertices.size());

      // For the tetrahedron (0, a, b, c) with signed volume V:
      //   int 1 dV = V, int x dV = V (a + b + c) / 4,
      //   int x x^T dV = V / 20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c.
      double          volume = 0.;
      Eigen::Vector3d first  = Eigen::Vector3d::Zero();
      Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
      for (const auto &t : mesh.triangles)
        {
          const Eigen::Vector3d a = mesh.vertices[t[0]] - o,
                                b = mesh.vertices[t[1]] - o,
                                c = mesh.vertices[t[2]] - o;
          const double          V = a.dot(b.cross(c)) / 6.;
          const Eigen::Vector3d s = a + b + c;
          volume += V;
          first += V / 4. * s;
          second += V / 20.
                    * (a * a.transpose() + b * b.transpose() + c * c.transpose()
                       + s * s.transpose());
        }
      if (!(volume > 0.))
        {
          std::ostringstream msg;
          msg << "compute_mass_properties: the mesh encloses a volume of "
              << volume
              << " (not positive). The surface must be closed and oriented "
                 "outward; read it with read_surface_mesh, which checks and "
                 "orients it.";
          throw GeometryError(msg.str());
        }

      MassProperties mp;
      mp.volume                 = volume;
      const Eigen::Vector3d g   = first / volume; // centre relative to o
      mp.centre                 = o + g;
      const Eigen::Matrix3d cov = second - volume * g * g.transpose();
      mp.inertia = cov.trace() * Eigen::Matrix3d::Identity() - cov;
      return mp;
    }

  } // namespace geometry
} // namespace particulate
