!> AFFE_CHAR_MECA FORCE_COQUE_FO: the PRES function evaluated once per cell, when the load is
!> defined, as Code_Aster's char_eval_fonc does: at the cell's centre (the mean of its
!> nodes' coordinates), with the parameters X, Y, Z, then EP (the shell's EPAIS, when the
!> command has CARA_ELEM and the cell a COQUE) and RHO (the ELAS RHO of the cell's material,
!> when the command has CHAM_MATER and the material ELAS with RHO). No INST: the pressure is
!> a constant per cell (DEFI_PRES_EC8's function needs EP and RHO). A function needing a
!> parameter the cell does not provide is an error, as in Code_Aster.
module force_coque_fo
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    use number_limits, only: is_finite, magnitude_fits
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use mesh_types, only: mesh_t, cell_label
    use model_concept, only: model_concept_t
    use cara_elem_concept, only: cara_elem_concept_t
    use material_concept, only: material_field_concept_t
    use function_concept, only: function_concept_t, param_binding_t
    use model_loads, only: load_set_t, load_set_cell_pressures
    implicit none
    private

    public :: force_coque_fo_pressures

contains

    !> Sets the PRES of item `index` (a FORCE_COQUE_FO occurrence `occ`, its cells already
    !> chosen) to the function's value at each cell's centre.
    !>  cmd : the AFFE_CHAR_MECA command (CARA_ELEM, CHAM_MATER)
    !>  st  : out, located at occ's PRES: not a function, CARA_ELEM / CHAM_MATER of another
    !>        mesh, the function's error at a cell (named), a value not finite or too large
    subroutine force_coque_fo_pressures(cmd, occ, mc, loads, index, st)
        type(command_t), intent(in) :: cmd
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        integer(i4), intent(in) :: index
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p, cara_p, mater_p
        type(cara_elem_concept_t), pointer :: cara
        type(material_field_concept_t), pointer :: mater
        real(dp), allocatable :: pres(:)
        character(len=:), allocatable :: why
        integer(i4) :: i
        cara => null()
        mater => null()
        call occ%get_concept('PRES', p, st)
        if (st%failed()) return
        if (cmd%has('CARA_ELEM')) then
            call cmd%get_concept('CARA_ELEM', cara_p, st)
            if (st%failed()) return
            select type (cara_p)
            type is (cara_elem_concept_t)
                cara => cara_p
            end select
        end if
        if (cmd%has('CHAM_MATER')) then
            call cmd%get_concept('CHAM_MATER', mater_p, st)
            if (st%failed()) return
            select type (mater_p)
            type is (material_field_concept_t)
                mater => mater_p
                if (size(mater%field%cell_material) /= mc%mesh%n_cells) then
                    call cmd%error_at('CHAM_MATER', 'the material field is on a mesh of ' // &
                        to_text(size(mater%field%cell_material, kind=i4)) // ' cells, the ' &
                        // 'model''s has ' // to_text(mc%mesh%n_cells), st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
            end select
        end if
        select type (p)
        class is (function_concept_t)
            associate (cells => loads%items(index)%cells)
                allocate (pres(size(cells)))
                do i = 1, size(cells)
                    call centre_value(p, mc%mesh, cells(i), cara, mater, pres(i), st)
                    if (st%failed()) then
                        why = st%message
                        call occ%error_at('PRES', why, st, code=STATUS_MODEL_ERROR)
                        return
                    end if
                end do
            end associate
        class default
            call occ%error_at('PRES', 'expected a function (DEFI_CONSTANTE, DEFI_FONCTION, ' &
                // 'FORMULE, DEFI_PRES_EC8), got ' // p%type_name(), st)
            return
        end select
        call load_set_cell_pressures(loads, index, pres)
    end subroutine force_coque_fo_pressures

    !> The function at the centre of cell c, with EP and RHO where the cell has them.
    subroutine centre_value(f, mesh, c, cara, mater, y, st)
        class(function_concept_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        type(cara_elem_concept_t), pointer, intent(in) :: cara
        type(material_field_concept_t), pointer, intent(in) :: mater
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        character(len=3) :: names(5)
        real(dp) :: values(5)
        type(param_binding_t) :: binding
        integer(i4) :: p0, nn, k, n, m
        p0 = mesh%cell_ptr(c)
        nn = mesh%cell_ptr(c + 1) - p0
        names(1:3) = ['X  ', 'Y  ', 'Z  ']
        do k = 1, 3
            values(k) = sum(mesh%coords(k, mesh%cell_nodes(p0:p0 + nn - 1))) / real(nn, dp)
        end do
        n = 3
        if (associated(cara)) then
            if (allocated(cara%cara%has_coque)) then
                if (c <= size(cara%cara%has_coque)) then
                    if (cara%cara%has_coque(c)) then
                        n = n + 1
                        names(n) = 'EP'
                        values(n) = cara%cara%thickness(c)
                    end if
                end if
            end if
        end if
        if (associated(mater)) then
            m = mater%field%cell_material(c)
            if (m > 0) then
                associate (mat => mater%field%materials(m))
                    if (mat%has_elas) then
                        if (mat%elas%has_rho) then
                            n = n + 1
                            names(n) = 'RHO'
                            values(n) = mat%elas%rho
                        end if
                    end if
                end associate
            end if
        end if
        call f%bind(names(1:n), binding)
        call f%evaluate(binding, values(1:n), y, st)
        if (st%failed()) then
            st%message = 'on ' // cell_label(mesh, c) // ': ' // st%message
            return
        end if
        if (.not. is_finite(y)) then
            call set_error(st, STATUS_MODEL_ERROR, 'PRES is not a finite number on ' // &
                cell_label(mesh, c))
        else if (.not. magnitude_fits(y)) then
            call set_error(st, STATUS_MODEL_ERROR, 'PRES = ' // to_text(y) // ' on ' // &
                cell_label(mesh, c) // ' is too large: the forces formed from it would overflow')
        end if
    end subroutine centre_value

end module force_coque_fo
