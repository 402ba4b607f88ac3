!> The section of a plate cell in its element's axes (model_plate_section turned by the
!> cell's user frame, element_plate_fields plate_user_turn): what the stiffness
!> (assembly_system) and the fields (plate_options) of DKT/DKQ cells take.
module assembly_plate_section
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use mesh_types, only: mesh_t, cell_label
    use model_material, only: material_field_t, material_of_cell
    use model_cara_elem, only: cara_elem_t
    use model_plate_section, only: plate_section_t, plate_section, section_in_element
    use element_plate_fields, only: plate_user_turn
    implicit none
    private

    public :: plate_cell_section

contains

    !> The section of plate cell c turned to the axes of its element (rot: rows = local
    !> x, y, normal, from plate_local_frame).
    !>  st : a missing material or thickness, a section that cannot be built, a user frame
    !>       normal to the cell; naming the cell
    subroutine plate_cell_section(mesh, materials, cara, c, rot, sec, st)
        type(mesh_t), intent(in) :: mesh
        type(material_field_t), intent(in) :: materials
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: rot(3, 3)
        type(plate_section_t), intent(out) :: sec
        type(status_t), intent(out) :: st
        type(plate_section_t) :: user
        real(dp) :: cs, sn
        integer(i4) :: m
        m = material_of_cell(materials, c)
        if (m == 0) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' has no material (give CHAM_MATER)')
            return
        end if
        call plate_section(materials%materials(m), cara, c, user, st)
        if (st%ok() .and. .not. user%isotropic) call plate_user_turn(rot, &
            cara%coque_direction(:, c), cs, sn, st)
        if (st%failed()) then
            call set_error(st, st%code, cell_label(mesh, c) // ': ' // st%message)
            return
        end if
        if (user%isotropic) then
            sec = user
        else
            call section_in_element(user, cs, sn, sec)
        end if
    end subroutine plate_cell_section

end module assembly_plate_section
