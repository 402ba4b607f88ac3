!> IMPR_RESU(FORMAT='RESULTAT') tables of the `.resu` listing (listings.md): per stored
!> instant, a header naming the result, field, NUME_ORDRE and INST, a column header, then one
!> line per node: the node name and the requested components in E format with 13 significant
!> digits (real_e13). A component a node does not carry is printed `-` so that columns stay
!> aligned token by token for parasol-diff; a node carrying none of them is left out.
!>
!>  ---- RESULTAT resu  NOM_CHAM DEPL  NUME_ORDRE 1  INST 1.000000000000E+00
!>  NOEUD    DX                    DZ
!>  N1       -3.532908704883E-03   0.000000000000E+00
module result_table
    use kinds, only: dp
    use strings, only: string_t, real_e13
    use result_data, only: node_field_t
    implicit none
    private

    !> Width of a value column: a 13-digit E value with a 3-digit exponent is 20 characters.
    integer, parameter :: VALUE_WIDTH = 22
    !> Smallest width of the node-name column (Code_Aster node names have up to 8 characters).
    integer, parameter :: NAME_WIDTH = 8
    !> Printed for a component the node does not carry.
    character(len=*), parameter, public :: RESULT_TABLE_ABSENT = '-'

    public :: resultat_table_lines, cell_table_lines

contains

    !> The lines of one RESULTAT table (ending with an empty line).
    !>  result_name : in, the result concept (e.g. resu)
    !>  nume_ordre  : in, NUME_ORDRE of the instant
    !>  inst        : in, INST of the instant
    !>  field       : in, the node field (components in the order they are printed; pass a
    !>                field restricted to NOM_CMP to print only those)
    !>  node_names  : in, (n_nodes) node names
    !>  lines       : out, the lines, without line ends
    !>  node_list   : in, optional, the nodes to print (1-based, in that order; default all)
    pure subroutine resultat_table_lines(result_name, nume_ordre, inst, field, node_names, &
                                         lines, node_list)
        character(len=*), intent(in) :: result_name
        integer, intent(in) :: nume_ordre
        real(dp), intent(in) :: inst
        type(node_field_t), intent(in) :: field
        type(string_t), intent(in) :: node_names(:)
        type(string_t), allocatable, intent(out) :: lines(:)
        integer, intent(in), optional :: node_list(:)
        integer, allocatable :: nodes(:)
        integer :: k, i, n, width
        character(len=12) :: buf
        character(len=:), allocatable :: row
        if (present(node_list)) then
            nodes = node_list
        else
            nodes = [(i, i = 1, size(node_names))]
        end if
        width = NAME_WIDTH
        do k = 1, size(nodes)
            width = max(width, len(node_names(nodes(k))%s))
        end do
        allocate (lines(size(nodes) + 3))
        write (buf, '(i0)') nume_ordre
        lines(1)%s = ' ---- RESULTAT ' // trim(result_name) // '  NOM_CHAM ' // field%name // &
                     '  NUME_ORDRE ' // trim(buf) // '  INST ' // real_e13(inst)
        row = ' ' // pad('NOEUD', width + 1)
        do i = 1, size(field%components)
            row = row // pad(trim(field%components(i)%s), VALUE_WIDTH)
        end do
        lines(2)%s = trim(row)
        n = 2
        do k = 1, size(nodes)
            if (.not. any(field%mask(:, nodes(k)))) cycle
            row = ' ' // pad(node_names(nodes(k))%s, width + 1)
            do i = 1, size(field%components)
                if (field%mask(i, nodes(k))) then
                    row = row // pad(real_e13(field%values(i, nodes(k))), VALUE_WIDTH)
                else
                    row = row // pad(RESULT_TABLE_ABSENT, VALUE_WIDTH)
                end if
            end do
            n = n + 1
            lines(n)%s = trim(row)
        end do
        n = n + 1
        lines(n)%s = ''
        lines = lines(1:n)
    end subroutine resultat_table_lines

    !> The lines of one RESULTAT table of an element field (ending with an empty line): the
    !> header as resultat_table_lines, then `MAILLE POINT` and the components, and one line
    !> per cell and point.
    !>  field      : in, the field name (SIEF_ELGA, VARI_ELGA)
    !>  components : in, the component names, in the order printed
    !>  cell_names : in, (n_cells) the cells, in the order printed
    !>  n_points   : in, points per cell (each point prints the cell's values)
    !>  values     : in, (n_components, n_cells)
    pure subroutine cell_table_lines(result_name, nume_ordre, inst, field, components, &
                                     cell_names, n_points, values, lines)
        character(len=*), intent(in) :: result_name, field
        integer, intent(in) :: nume_ordre, n_points
        real(dp), intent(in) :: inst, values(:, :)
        type(string_t), intent(in) :: components(:), cell_names(:)
        type(string_t), allocatable, intent(out) :: lines(:)
        integer :: k, i, p, n, width
        character(len=12) :: buf
        character(len=:), allocatable :: row
        width = NAME_WIDTH
        do k = 1, size(cell_names)
            width = max(width, len(cell_names(k)%s))
        end do
        allocate (lines(size(cell_names) * n_points + 3))
        write (buf, '(i0)') nume_ordre
        lines(1)%s = ' ---- RESULTAT ' // trim(result_name) // '  NOM_CHAM ' // field // &
                     '  NUME_ORDRE ' // trim(buf) // '  INST ' // real_e13(inst)
        row = ' ' // pad('MAILLE', width + 1) // pad('POINT', NAME_WIDTH)
        do i = 1, size(components)
            row = row // pad(components(i)%s, VALUE_WIDTH)
        end do
        lines(2)%s = trim(row)
        n = 2
        do k = 1, size(cell_names)
            do p = 1, n_points
                write (buf, '(i0)') p
                row = ' ' // pad(cell_names(k)%s, width + 1) // pad(trim(buf), NAME_WIDTH)
                do i = 1, size(components)
                    row = row // pad(real_e13(values(i, k)), VALUE_WIDTH)
                end do
                n = n + 1
                lines(n)%s = trim(row)
            end do
        end do
        n = n + 1
        lines(n)%s = ''
    end subroutine cell_table_lines

    !> `text` left-aligned in `width` columns, or followed by one blank when longer.
    pure function pad(text, width) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function pad

end module result_table
