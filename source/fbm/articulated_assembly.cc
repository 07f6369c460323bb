#include <particulate/fbm/articulated_assembly.h>

namespace particulate {
  namespace fbm {
    unsigned int
    assembly_head(const std::vector<ParticleDescription> &particles,
                  const unsigned int                      i)
    {
      return particles[i].motion == ParticleMotion::hinged ?
               particles[i].hinge.parent :
               i;
    }



    std::vector<std::vector<unsigned int>>
    hinged_parts(const std::vector<ParticleDescription> &particles)
    {
      std::vector<std::vector<unsigned int>> parts(particles.size());
      for (unsigned int i = 0; i < particles.size(); ++i)
        if (particles[i].motion == ParticleMotion::hinged)
          parts[particles[i].hinge.parent].push_back(i);
      return parts;
    }



    AssemblyInertia
    assembly_inertia(const std::vector<ParticleDescription> &particles,
                     const std::vector<BodyStart>           &starts,
                     const unsigned int                      head,
                     const std::vector<unsigned int>        &parts,
                     const double                            extra_density)
    {
      const Eigen::Vector3d    &centre = starts[head].position;
      AssemblyInertia           result;
      std::vector<unsigned int> members(1, head);
      members.insert(members.end(), parts.begin(), parts.end());
      for (const unsigned int j : members)
        {
          const ParticleDescription &p   = particles[j];
          const double               rho = p.density + extra_density;
          const double               m   = rho * p.shape->volume();
          const Eigen::Matrix3d R = starts[j].orientation.toRotationMatrix();
          const Eigen::Vector3d r = starts[j].position - centre;
          result.mass += m;
          result.inertia += R * (rho * p.shape->unit_inertia()) * R.transpose()
                            + m
                                * (r.squaredNorm() * Eigen::Matrix3d::Identity()
                                   - r * r.transpose());
        }
      const Eigen::Matrix3d R_head
        = starts[head].orientation.toRotationMatrix();
      result.inertia = R_head.transpose() * result.inertia * R_head;
      return result;
    }
  } // namespace fbm
} // namespace particulate
