!> Thermal strains of the structure at an instant (AFFE_VARC TEMP, model_varc; the
!> material's expansion, model_thermal): the nodal forces they give (add_varc_forces, part
!> of f_ext at every instant of MECA_STATIQUE and STAT_NON_LINE), and the strains
!> themselves at the points of a cell, which the stresses subtract (CALC_CHAMP, SIEF_ELGA):
!>  - plane cells (D_PLAN, C_PLAN): eps_th = (e, e, e, 0) on (xx, yy, zz, xy) at each point,
!>    e the material's thermal strain at the temperature interpolated from the nodes with
!>    the cell's shape functions; D_PLAN restrains the zz part (element_plane);
!>  - plates (DKT, DKQ): the strain at each sub-point of the thickness (3 per COQUE_NCOU
!>    layer, element_plate_initial_strains), from a temperature uniform through the
!>    thickness (TEMP), parabolic through it (TEMP_INF, TEMP_MIL, TEMP_SUP: T(z) = T_MIL +
!>    (T_SUP - T_INF) z/h + 2 (T_INF + T_SUP - 2 T_MIL) z^2/h^2, Code_Aster's te0408), or
!>    given at the sub-points (CREA_RESU PREP_VARC); the forces of the membrane and bending
!>    thermal resultants N0 = int Dm eps_th dz, M0 = int Dm eps_th z dz.
!> Cells whose material has no ALPHA get nothing, with or without a temperature.
!>
!> The shrinkage of the hydration and the drying (AFFE_VARC HYDR and SECH; B_ENDOGE and
!> K_DESSIC, model_thermal) adds to the thermal strain of plane cells, interpolated from the
!> nodes at each point as the temperature (Code_Aster's CHAR_MECA_HYDR_R / SECH_R on its
!> C_PLAN and D_PLAN elements). Code_Aster's plates (DKT, DKQ: te0312) do not take them: a
!> plate cell that sees HYDR with B_ENDOGE /= 0, or SECH with K_DESSIC /= 0, is a located
!> error, as there.
module assembly_varc
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, real_e13
    use number_limits, only: product_fits, MAX_LENGTH
    use mesh_types, only: mesh_t, cell_label, CELL_TYPE_NODES, MAX_CELL_NODES, CELL_TRIA3, &
        CELL_QUAD4
    use mesh_cell_shapes, only: cell_shape
    use model_types, only: model_t, is_plate, is_plane_solid, ELEMENT_NAMES
    use model_material, only: material_field_t, material_t, material_of_cell, behaviour_number
    use model_cara_elem, only: cara_elem_t
    use model_varc, only: cell_temperature_t, varc_cell_temperature, varc_has_any, &
        varc_cell_has, varc_cell_scalar, TEMP_NONE, TEMP_UNIFORM, TEMP_PROFILE, &
        TEMP_SUBPOINTS, VARC_HYDR, VARC_SECH
    use model_thermal, only: thermal_strain, has_thermal_expansion, shrinks_with, &
        shrinkage_strain, SHRINKAGE_KEY_HYDR, SHRINKAGE_KEY_SECH
    use element_gauss_families, only: gauss_rule_t
    use element_plane, only: plane_law_t, plane_rigi_rule, plane_initial_strain_forces
    use assembly_plane_law, only: plane_cell_law
    use element_plate_initial_strains, only: plate_rigi_rule, plate_layer_points, &
        plate_initial_strain_forces
    use assembly_system, only: structure_t, element_equations, MAX_ELEMENT_DOFS
    use model_plate_section, only: plate_section_t, plate_section
    implicit none
    private

    public :: add_varc_forces, plane_thermal_strains, plate_thermal_strains, has_thermal_load

contains

    !> True when some cell of the structure has a temperature and a thermal expansion.
    logical function has_thermal_load(s)
        type(structure_t), intent(in) :: s
        has_thermal_load = varc_has_any(s%materials%varc)
    end function has_thermal_load

    !> fext += the nodal forces of the thermal strains at instant t (module header).
    !>  st : out, a temperature missing on a cell, an instant outside an EVOL, a thermal
    !>       profile on a plane cell; naming the cell
    subroutine add_varc_forces(s, t, fext, st)
        type(structure_t), intent(in) :: s
        real(dp), intent(in) :: t
        real(dp), intent(inout) :: fext(:)
        type(status_t), intent(out) :: st
        integer(i4) :: c, kind, m, n, j, eqs(MAX_ELEMENT_DOFS)
        real(dp) :: fe(MAX_ELEMENT_DOFS)
        logical :: orthotropic, expands
        if (.not. varc_has_any(s%materials%varc)) return
        do c = 1, s%mesh%n_cells
            if (.not. varc_cell_has(s%materials%varc, c)) cycle
            kind = s%model%element(c)
            if (.not. (is_plate(kind) .or. is_plane_solid(kind))) cycle
            m = material_of_cell(s%materials, c)
            if (m == 0) cycle
            orthotropic = .false.
            if (is_plane_solid(kind)) orthotropic = &
                orthotropic_expansion(s%materials%materials(m))
            if (orthotropic) then
                call set_error(st, STATUS_NOT_IMPLEMENTED, cell_label(s%mesh, c) // ': the ' &
                    // 'thermal strains of ELAS_ORTH (ALPHA_L, ALPHA_T, ALPHA_N) are not ' // &
                    'built; its temperature would be ignored')
                return
            end if
            expands = has_thermal_expansion(s%materials%materials(m))
            if (.not. expands) expands = shrinks(s%materials%materials(m))
            if (.not. expands) cycle
            call element_equations(s, c, eqs, n)
            if (is_plane_solid(kind)) then
                call plane_cell_forces(s, c, t, fe(1:n), st)
            else
                call plate_cell_forces(s, c, t, fe(1:n), st)
            end if
            if (st%failed()) return
            do j = 1, n
                if (eqs(j) > 0) fext(eqs(j)) = fext(eqs(j)) + fe(j)
            end do
        end do
    end subroutine add_varc_forces

    ! True when the material gives a shrinkage coefficient (B_ENDOGE or K_DESSIC) not zero.
    logical function shrinks(mat)
        type(material_t), intent(in) :: mat
        logical :: sech
        shrinks = shrinks_with(mat, SHRINKAGE_KEY_HYDR)
        sech = shrinks_with(mat, SHRINKAGE_KEY_SECH)
        shrinks = shrinks .or. sech
    end function shrinks

    ! True when the material's ELAS_ORTH gives a thermal expansion (an ALPHA_* not zero).
    logical function orthotropic_expansion(mat)
        type(material_t), intent(in) :: mat
        character(len=7), parameter :: KEYS(3) = ['ALPHA_L', 'ALPHA_T', 'ALPHA_N']
        real(dp) :: a
        logical :: found
        integer(i4) :: k
        orthotropic_expansion = .false.
        do k = 1, 3
            call behaviour_number(mat, 'ELAS_ORTH', KEYS(k), a, found)
            if (found .and. abs(a) > 0.0_dp) orthotropic_expansion = .true.
        end do
    end function orthotropic_expansion

    !> Command-variable strains (xx, yy, zz, xy engineering) at the points of `rule` on
    !> plane cell c at instant t: the thermal strain plus the shrinkage of HYDR and SECH
    !> (module header); all zero (and has = .false.) when the cell sees none of them or
    !> its material has no ALPHA, B_ENDOGE or K_DESSIC.
    !>  eps : out, eps(4, rule%n)
    subroutine plane_thermal_strains(mesh, model, materials, c, t, rule, eps, has, st)
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        type(material_field_t), intent(in) :: materials
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t
        type(gauss_rule_t), intent(in) :: rule
        real(dp), intent(out) :: eps(:, :)
        logical, intent(out) :: has
        type(status_t), intent(out) :: st
        type(cell_temperature_t) :: temp
        real(dp), allocatable :: hydr(:), sech(:)
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), tg, e, e_var, sref, unused
        integer(i4) :: g, m, nn, ctype
        logical :: has_t, has_h, has_s
        eps = 0.0_dp
        call expanding_cell(mesh, materials, c, t, m, temp, has_t, st)
        if (st%failed()) return
        if (has_t .and. temp%kind /= TEMP_UNIFORM) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' (' // &
                trim(ELEMENT_NAMES(model%element(c))) // '): TEMP_INF, TEMP_MIL, ' // &
                'TEMP_SUP and layers are for plates; a plane element takes TEMP')
            return
        end if
        call shrinking_cell(mesh, materials, c, t, VARC_HYDR, SHRINKAGE_KEY_HYDR, hydr, &
                            unused, has_h, st)
        if (st%ok()) call shrinking_cell(mesh, materials, c, t, VARC_SECH, &
            SHRINKAGE_KEY_SECH, sech, sref, has_s, st)
        if (st%failed()) return
        has = has_t .or. has_h .or. has_s
        if (.not. has) return
        m = material_of_cell(materials, c)
        ctype = mesh%cell_type(c)
        nn = CELL_TYPE_NODES(ctype)
        do g = 1, rule%n
            call cell_shape(ctype, rule%xi(1, g), rule%xi(2, g), n(1:nn), dn(:, 1:nn))
            e = 0.0_dp
            if (has_t) then
                tg = dot_product(n(1:nn), temp%t(1, 1:nn))
                call thermal_strain(materials%materials(m), tg, temp%vale_ref, e, st)
            end if
            if (st%ok() .and. has_h) then
                call shrinkage_strain(materials%materials(m), SHRINKAGE_KEY_HYDR, &
                    dot_product(n(1:nn), hydr(1:nn)), 0.0_dp, e_var, st)
                e = e + e_var
            end if
            if (st%ok() .and. has_s) then
                call shrinkage_strain(materials%materials(m), SHRINKAGE_KEY_SECH, &
                    dot_product(n(1:nn), sech(1:nn)), sref, e_var, st)
                e = e + e_var
            end if
            if (st%failed()) then
                call set_error(st, st%code, cell_label(mesh, c) // ': ' // st%message)
                return
            end if
            eps(1:3, g) = e
        end do
    end subroutine plane_thermal_strains

    ! The nodal values of command variable `variable` on cell c at instant t, when the
    ! cell sees it and its material's shrinkage coefficient `key` is not zero (has).
    subroutine shrinking_cell(mesh, materials, c, t, variable, key, values, vref, has, st)
        type(mesh_t), intent(in) :: mesh
        type(material_field_t), intent(in) :: materials
        integer(i4), intent(in) :: c, variable
        real(dp), intent(in) :: t
        character(len=*), intent(in) :: key
        real(dp), allocatable, intent(out) :: values(:)
        real(dp), intent(out) :: vref
        logical, intent(out) :: has
        type(status_t), intent(out) :: st
        integer(i4) :: m
        has = .false.
        vref = 0.0_dp
        m = material_of_cell(materials, c)
        if (m == 0) return
        if (.not. shrinks_with(materials%materials(m), key)) return
        call varc_cell_scalar(materials%varc, mesh, c, variable, t, values, vref, has, st)
    end subroutine shrinking_cell

    ! Thermal forces of a plane cell (element_plane: D_PLAN's restrained zz included).
    subroutine plane_cell_forces(s, c, t, fe, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        type(plane_law_t) :: law
        real(dp), allocatable :: eps(:, :), xy(:, :)
        real(dp) :: dmax
        integer(i4) :: nn, p0
        logical :: has, fits
        fe = 0.0_dp
        call plane_rigi_rule(s%mesh%cell_type(c), rule, st)
        if (st%failed()) return
        allocate (eps(4, rule%n))
        call plane_thermal_strains(s%mesh, s%model, s%materials, c, t, rule, eps, has, st)
        if (st%failed() .or. .not. has) return
        call plane_cell_law(s%mesh, s%model, s%materials, s%cara, c, law, st)
        if (st%failed()) then
            call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
            return
        end if
        ! the stress D eps0 and the forces B^T D eps0 |J| w must stay finite (issue 13): a
        ! strain from a temperature of 1e308 stops here, located, instead of overflowing
        ! (B |J| w is at most a length, MAX_LENGTH; the moduli at most MAX_MODULUS)
        dmax = 16.0_dp * max(maxval(abs(law%d4)), maxval(abs(law%d3)))
        fits = product_fits(maxval(abs(eps)), dmax)
        if (fits) fits = product_fits(maxval(abs(eps)) * dmax, MAX_LENGTH)
        if (.not. fits) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(s%mesh, c) // ': a command-' // &
                'variable strain of ' // real_e13(maxval(abs(eps))) // ' (AFFE_VARC TEMP, ' // &
                'HYDR, SECH) gives stresses beyond double precision; check the fields ' // &
                'and ALPHA, B_ENDOGE, K_DESSIC')
            return
        end if
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        xy = s%mesh%coords(1:2, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call plane_initial_strain_forces(s%mesh%cell_type(c), xy, law, eps, fe, st)
        if (st%failed()) call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // &
            st%message)
    end subroutine plane_cell_forces

    !> The thermal strain at each sub-point (3 per COQUE_NCOU layer, INF MOY SUP from the
    !> bottom) of each point xi(2, n_points) of plate cell c at instant t (isotropic: the
    !> same in xx and yy, none in shear); zero and has = .false. without a temperature or
    !> ALPHA.
    !>  eps : out, eps(3 layers, n_points)
    subroutine plate_thermal_strains(mesh, materials, cara, c, t, xi, eps, has, st)
        type(mesh_t), intent(in) :: mesh
        type(material_field_t), intent(in) :: materials
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t, xi(:, :)
        real(dp), intent(out) :: eps(:, :)
        logical, intent(out) :: has
        type(status_t), intent(out) :: st
        type(cell_temperature_t) :: temp
        real(dp) :: n(4), dn(2, 4), tp(3), z(3 * cara%coque_layers(c)), w(3 * cara%coque_layers(c))
        real(dp) :: h, tz, cp1, cp2, cp3
        integer(i4) :: g, m, nn, layers, k, nsub
        eps = 0.0_dp
        has = .false.
        call refuse_plate_shrinkage(mesh, materials, c, st)
        if (st%failed()) return
        call expanding_cell(mesh, materials, c, t, m, temp, has, st)
        if (.not. has) return
        layers = cara%coque_layers(c)
        nsub = 3 * layers
        h = cara%thickness(c)
        call plate_layer_points(h, layers, z, w)
        if (temp%kind == TEMP_SUBPOINTS .and. temp%n_sub /= nsub) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ': the ' // &
                'temperature has ' // to_text(temp%n_sub) // ' sub-points, the plate ' // &
                to_text(layers) // ' layer(s) (COQUE_NCOU) of 3 sub-points each')
            return
        end if
        nn = temp%nn
        do g = 1, size(xi, 2)
            call cell_shape(merge(CELL_TRIA3, CELL_QUAD4, nn == 3), xi(1, g), xi(2, g), &
                            n(1:nn), dn(:, 1:nn))
            do k = 1, nsub
                select case (temp%kind)
                case (TEMP_UNIFORM)
                    tz = dot_product(n(1:nn), temp%t(1, 1:nn))
                case (TEMP_PROFILE)
                    tp = matmul(temp%t(:, 1:nn), n(1:nn))        ! INF, MIL, SUP
                    cp1 = tp(2)
                    cp2 = (tp(3) - tp(1)) / h
                    cp3 = 2.0_dp * (tp(1) + tp(3) - 2.0_dp * tp(2)) / (h * h)
                    tz = cp1 + cp2 * z(k) + cp3 * z(k)**2
                case default
                    tz = dot_product(n(1:nn), temp%t(k, 1:nn))
                end select
                call thermal_strain(materials%materials(m), tz, temp%vale_ref, eps(k, g), st)
                if (st%failed()) then
                    call set_error(st, st%code, cell_label(mesh, c) // ': ' // st%message)
                    return
                end if
            end do
        end do
    end subroutine plate_thermal_strains

    ! Thermal forces of a plate cell: N0, M0 at the RIGI points from the sub-point strains.
    subroutine plate_cell_forces(s, c, t, fe, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp), allocatable :: eps(:, :), z(:), w(:), n0(:, :), m0(:, :)
        real(dp) :: dm(3, 3), x(3, 4), unit(3)
        type(plate_section_t) :: sec
        integer(i4) :: nn, m, g, layers, p0
        logical :: has
        fe = 0.0_dp
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        call plate_rigi_rule(nn, rule, st)
        if (st%failed()) return
        layers = s%cara%coque_layers(c)
        allocate (eps(3 * layers, rule%n), z(3 * layers), w(3 * layers))
        call plate_thermal_strains(s%mesh, s%materials, s%cara, c, t, rule%xi(:, 1:rule%n), &
            eps, has, st)
        if (st%failed() .or. .not. has) return
        call plate_layer_points(s%cara%thickness(c), layers, z, w)
        m = material_of_cell(s%materials, c)
        call plate_section(s%materials%materials(m), s%cara, c, sec, st)
        if (st%failed()) then
            call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
            return
        end if
        if (.not. sec%isotropic) then
            call set_error(st, STATUS_NOT_IMPLEMENTED, cell_label(s%mesh, c) // ': the ' // &
                'thermal strains of a plate are built for ELAS and ELAS_FO sections')
            return
        end if
        dm = sec%dm / sec%thickness                      ! the plane-stress matrix
        unit = matmul(dm, [1.0_dp, 1.0_dp, 0.0_dp])      ! the stress of a unit expansion
        z = z + sec%offset                               ! about the reference surface
        allocate (n0(3, rule%n), m0(3, rule%n))
        do g = 1, rule%n
            n0(:, g) = unit * sum(w * eps(:, g))
            m0(:, g) = unit * sum(w * z * eps(:, g))
        end do
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        call plate_initial_strain_forces(x(:, 1:nn), nn, n0, m0, fe, st)
        if (st%failed()) call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // &
            st%message)
    end subroutine plate_cell_forces

    ! Code_Aster's plates refuse the shrinkage strains (te0312): a plate cell seeing HYDR
    ! with B_ENDOGE /= 0 or SECH with K_DESSIC /= 0 is an error, naming the cell.
    subroutine refuse_plate_shrinkage(mesh, materials, c, st)
        type(mesh_t), intent(in) :: mesh
        type(material_field_t), intent(in) :: materials
        integer(i4), intent(in) :: c
        type(status_t), intent(out) :: st
        integer(i4) :: m
        logical :: hydr, sech
        m = material_of_cell(materials, c)
        if (m == 0) return
        hydr = shrinks_with(materials%materials(m), SHRINKAGE_KEY_HYDR)
        sech = shrinks_with(materials%materials(m), SHRINKAGE_KEY_SECH)
        if (hydr .and. varc_cell_has(materials%varc, c, VARC_HYDR)) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ': a plate ' // &
                '(DKT, DKQ) does not take the endogenous shrinkage of AFFE_VARC HYDR; ' // &
                'its material gives B_ENDOGE /= 0 (Code_Aster refuses it too: give ' // &
                'B_ENDOGE = 0 or no HYDR on the plates)')
        else if (sech .and. varc_cell_has(materials%varc, c, VARC_SECH)) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ': a plate ' // &
                '(DKT, DKQ) does not take the desiccation shrinkage of AFFE_VARC SECH; ' // &
                'its material gives K_DESSIC /= 0 (Code_Aster refuses it too: give ' // &
                'K_DESSIC = 0 or no SECH on the plates)')
        end if
    end subroutine refuse_plate_shrinkage

    ! The material m and temperature of cell c at instant t; has = .false. (and nothing to
    ! do) when the cell has no material, no ALPHA or no temperature.
    subroutine expanding_cell(mesh, materials, c, t, m, temp, has, st)
        type(mesh_t), intent(in) :: mesh
        type(material_field_t), intent(in) :: materials
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t
        integer(i4), intent(out) :: m
        type(cell_temperature_t), intent(out) :: temp
        logical, intent(out) :: has
        type(status_t), intent(out) :: st
        has = .false.
        m = material_of_cell(materials, c)
        if (m == 0) return
        if (.not. has_thermal_expansion(materials%materials(m))) return
        call varc_cell_temperature(materials%varc, mesh, c, t, temp, st)
        has = st%ok() .and. temp%kind /= TEMP_NONE
    end subroutine expanding_cell

end module assembly_varc
