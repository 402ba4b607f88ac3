!> Merging of the materials of one AFFE_MATERIAU occurrence, MATER=(A, B): as in
!> Code_Aster, a cell may receive several materials as long as each behaviour (ELAS,
!> DIS_CONTACT, THER, ...) is defined by at most one of them (U4.43.03, AFFE_MATERIAU/MATER).
module model_material_merge
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use model_material, only: material_t, add_behaviour, has_behaviour
    implicit none
    private

    public :: merge_materials

contains

    !> The material made of the behaviours of `materials`; its name joins theirs with '+'.
    !>  materials : in, at least one material
    !>  merged    : out, the union of their parts
    !>  st        : out, STATUS_MODEL_ERROR when two materials define the same behaviour
    !>              (naming them and it), or when the list is empty
    subroutine merge_materials(materials, merged, st)
        type(material_t), intent(in) :: materials(:)
        type(material_t), intent(out) :: merged
        type(status_t), intent(out) :: st
        integer :: k, elas_from, contact_from, b, other
        if (size(materials) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'MATER needs at least one material')
            return
        end if
        elas_from = 0
        contact_from = 0
        merged%name = ''
        do k = 1, size(materials)
            if (k > 1) merged%name = merged%name // '+'
            merged%name = merged%name // label(materials(k))
            if (materials(k)%has_elas) then
                if (elas_from > 0) then
                    call twice('ELAS', elas_from, k)
                    return
                end if
                elas_from = k
                merged%has_elas = .true.
                merged%elas = materials(k)%elas
            end if
            if (materials(k)%has_dis_contact) then
                if (contact_from > 0) then
                    call twice('DIS_CONTACT', contact_from, k)
                    return
                end if
                contact_from = k
                merged%has_dis_contact = .true.
                merged%dis_contact = materials(k)%dis_contact
            end if
            if (.not. allocated(materials(k)%behaviours)) cycle
            do b = 1, size(materials(k)%behaviours)
                associate (name => materials(k)%behaviours(b)%name)
                    if (has_behaviour(merged, name)) then
                        do other = 1, k - 1
                            if (has_behaviour(materials(other), name)) exit
                        end do
                        call twice(name, other, k)
                        return
                    end if
                    call add_behaviour(merged, materials(k)%behaviours(b))
                end associate
            end do
        end do
    contains
        subroutine twice(part, first, second)
            character(len=*), intent(in) :: part
            integer, intent(in) :: first, second
            call set_error(st, STATUS_MODEL_ERROR, 'materials ' // label(materials(first)) &
                // ' and ' // label(materials(second)) // ' both define ' // part // &
                ': a cell takes each behaviour from one material only')
        end subroutine twice
    end subroutine merge_materials

    pure function label(mat) result(text)
        type(material_t), intent(in) :: mat
        character(len=:), allocatable :: text
        text = '(unnamed)'
        if (allocated(mat%name)) then
            if (len(mat%name) > 0) text = mat%name
        end if
    end function label

end module model_material_merge
